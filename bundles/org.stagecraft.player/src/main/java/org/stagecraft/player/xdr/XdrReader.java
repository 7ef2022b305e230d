package org.stagecraft.player.xdr;

/**
 * Reads Sun XDR (RFC 4506) items from a byte array: big-endian, every item padded to 4 bytes.
 * Counts read from the input are checked against the bytes that remain before anything is
 * allocated, so a hostile count can never drive an allocation.
 */
public final class XdrReader {
    private final byte[] buf;
    private final int start;
    private final int limit;
    private int pos;

    public XdrReader(byte[] buf) {
        this(buf, 0, buf.length);
    }

    public XdrReader(byte[] buf, int offset, int length) {
        this.buf = buf;
        this.start = offset;
        this.pos = offset;
        this.limit = offset + length;
    }

    /** Offset relative to the start of the region being read. */
    public int position() {
        return pos - start;
    }

    public int remaining() {
        return limit - pos;
    }

    private void need(int n) {
        if (n < 0 || limit - pos < n) {
            throw new XdrException(position(), "truncated: need " + n + " bytes, " + remaining() + " left");
        }
    }

    public int int32() {
        need(4);
        int v = ((buf[pos] & 0xFF) << 24) | ((buf[pos + 1] & 0xFF) << 16) | ((buf[pos + 2] & 0xFF) << 8)
                | (buf[pos + 3] & 0xFF);
        pos += 4;
        return v;
    }

    /** An unsigned 32-bit value kept in an int; callers print it with Integer.toUnsignedLong. */
    public int uint32() {
        return int32();
    }

    public long int64() {
        long hi = int32() & 0xFFFFFFFFL;
        long lo = int32() & 0xFFFFFFFFL;
        return (hi << 32) | lo;
    }

    /** xdr_u_char: one byte carried in a 4-byte word; any other high bits are not canonical XDR. */
    public int uint8() {
        int at = position();
        int v = int32();
        if ((v & 0xFFFFFF00) != 0) {
            throw new XdrException(at, "uint8 word 0x" + Integer.toHexString(v) + " is out of range");
        }
        return v;
    }

    /** xdr_char: a signed byte sign-extended into a 4-byte word. */
    public int int8() {
        int at = position();
        int v = int32();
        if (v < -128 || v > 127) {
            throw new XdrException(at, "int8 word 0x" + Integer.toHexString(v) + " is out of range");
        }
        return v;
    }

    public int uint16() {
        int at = position();
        int v = int32();
        if ((v & 0xFFFF0000) != 0) {
            throw new XdrException(at, "uint16 word 0x" + Integer.toHexString(v) + " is out of range");
        }
        return v;
    }

    public int int16() {
        int at = position();
        int v = int32();
        if (v < Short.MIN_VALUE || v > Short.MAX_VALUE) {
            throw new XdrException(at, "int16 word 0x" + Integer.toHexString(v) + " is out of range");
        }
        return v;
    }

    public boolean bool() {
        int at = position();
        int v = int32();
        if (v != 0 && v != 1) {
            throw new XdrException(at, "bool word " + v + " is neither 0 nor 1");
        }
        return v == 1;
    }

    public float float32() {
        return Float.intBitsToFloat(int32());
    }

    public double float64() {
        return Double.longBitsToDouble(int64());
    }

    /**
     * Reads an array length and checks that {@code count * minElementBytes} bytes remain.
     */
    public int count(int minElementBytes) {
        int at = position();
        int n = int32();
        if (n < 0 || (long) n * minElementBytes > remaining()) {
            throw new XdrException(at, "array count " + Integer.toUnsignedLong(n) + " needs more than the "
                    + remaining() + " bytes left");
        }
        return n;
    }

    /** xdr_bytes: count, bytes, zero padding to 4. */
    public byte[] bytes() {
        int n = count(1);
        return opaque(n);
    }

    /** xdr_opaque of a known length: bytes and padding to 4. */
    public byte[] opaque(int n) {
        int padded = (n + 3) & ~3;
        need(padded);
        byte[] out = new byte[n];
        System.arraycopy(buf, pos, out, 0, n);
        int at = position();
        for (int i = n; i < padded; i++) {
            if (buf[pos + i] != 0) {
                throw new XdrException(at + i, "non-zero XDR padding");
            }
        }
        pos += padded;
        return out;
    }

    public float[] float32Array(int n) {
        need(n * 4);
        float[] out = new float[n];
        for (int i = 0; i < n; i++) {
            out[i] = Float.intBitsToFloat(int32());
        }
        return out;
    }

    public double[] float64Array(int n) {
        need(n * 8);
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            out[i] = Double.longBitsToDouble(int64());
        }
        return out;
    }

    /** Fails unless every byte has been consumed: a decoded struct must account for the whole payload. */
    public void expectEnd() {
        if (pos != limit) {
            throw new XdrException(position(), remaining() + " trailing bytes after the decoded struct");
        }
    }
}
