package org.stagecraft.player.xdr;

import java.util.Arrays;

/** Writes Sun XDR items into a growable buffer; the mirror of {@link XdrReader}. */
public final class XdrWriter {
    private byte[] buf;
    private int pos;

    public XdrWriter() {
        this(256);
    }

    public XdrWriter(int capacity) {
        buf = new byte[Math.max(16, capacity)];
    }

    private void ensure(int n) {
        if (buf.length - pos < n) {
            buf = Arrays.copyOf(buf, Math.max(buf.length * 2, pos + n));
        }
    }

    public int size() {
        return pos;
    }

    public XdrWriter int32(int v) {
        ensure(4);
        buf[pos] = (byte) (v >>> 24);
        buf[pos + 1] = (byte) (v >>> 16);
        buf[pos + 2] = (byte) (v >>> 8);
        buf[pos + 3] = (byte) v;
        pos += 4;
        return this;
    }

    public XdrWriter uint32(int v) {
        return int32(v);
    }

    public XdrWriter int64(long v) {
        int32((int) (v >>> 32));
        return int32((int) v);
    }

    public XdrWriter uint8(int v) {
        return int32(v & 0xFF);
    }

    public XdrWriter int8(int v) {
        return int32((byte) v);
    }

    public XdrWriter uint16(int v) {
        return int32(v & 0xFFFF);
    }

    public XdrWriter int16(int v) {
        return int32((short) v);
    }

    public XdrWriter bool(boolean v) {
        return int32(v ? 1 : 0);
    }

    /** Raw bits, so NaN payloads and uninitialised values survive a round trip. */
    public XdrWriter float32(float v) {
        return int32(Float.floatToRawIntBits(v));
    }

    public XdrWriter float64(double v) {
        return int64(Double.doubleToRawLongBits(v));
    }

    public XdrWriter bytes(byte[] data) {
        int32(data.length);
        return opaque(data);
    }

    public XdrWriter opaque(byte[] data) {
        int padded = (data.length + 3) & ~3;
        ensure(padded);
        System.arraycopy(data, 0, buf, pos, data.length);
        Arrays.fill(buf, pos + data.length, pos + padded, (byte) 0);
        pos += padded;
        return this;
    }

    public XdrWriter raw(byte[] data, int off, int len) {
        ensure(len);
        System.arraycopy(data, off, buf, pos, len);
        pos += len;
        return this;
    }

    public byte[] toByteArray() {
        return Arrays.copyOf(buf, pos);
    }
}
