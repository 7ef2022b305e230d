package org.stagecraft.mcap;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/** A growable little-endian byte buffer that MCAP records are written into. */
public final class RecordBuffer {
    private byte[] a;
    private int n;

    public RecordBuffer(int capacity) {
        a = new byte[Math.max(16, capacity)];
    }

    public int size() {
        return n;
    }

    public byte[] array() {
        return a;
    }

    public void clear() {
        n = 0;
    }

    public byte[] toByteArray() {
        return Arrays.copyOf(a, n);
    }

    private void room(int more) {
        if (n + more > a.length) {
            long want = Math.max((long) a.length * 2, (long) n + more);
            if (want > Integer.MAX_VALUE - 16) {
                throw new IllegalStateException("buffer over 2 GiB");
            }
            a = Arrays.copyOf(a, (int) want);
        }
    }

    public RecordBuffer u8(int v) {
        room(1);
        a[n++] = (byte) v;
        return this;
    }

    public RecordBuffer u16(int v) {
        room(2);
        a[n++] = (byte) v;
        a[n++] = (byte) (v >>> 8);
        return this;
    }

    public RecordBuffer u32(long v) {
        room(4);
        for (int i = 0; i < 4; i++) {
            a[n++] = (byte) (v >>> (8 * i));
        }
        return this;
    }

    public RecordBuffer u64(long v) {
        room(8);
        for (int i = 0; i < 8; i++) {
            a[n++] = (byte) (v >>> (8 * i));
        }
        return this;
    }

    public RecordBuffer bytes(byte[] b, int off, int len) {
        room(len);
        System.arraycopy(b, off, a, n, len);
        n += len;
        return this;
    }

    public RecordBuffer bytes(byte[] b) {
        return bytes(b, 0, b.length);
    }

    /** Makes room for {@code len} bytes written later into {@link #array()} at the returned position. */
    public int reserve(int len) {
        room(len);
        int at = n;
        n += len;
        return at;
    }

    /** Cuts the buffer back to {@code size} bytes (e.g. after a {@link #reserve} that was not used up). */
    public void truncate(int size) {
        if (size < 0 || size > n) {
            throw new IllegalArgumentException("size " + size + " of " + n);
        }
        n = size;
    }

    public RecordBuffer string(String s) {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        u32(b.length);
        return bytes(b);
    }

    /** Starts a record: opcode and a length placeholder; returns the position to pass to {@link #end}. */
    public int begin(int opcode) {
        u8(opcode);
        int at = n;
        u64(0);
        return at;
    }

    /** Patches the content length of the record begun at {@code at}. */
    public void end(int at) {
        putU64(at, n - at - 8);
    }

    /** Starts a u32 byte-length prefix (Map, Array); returns the position for {@link #endU32}. */
    public int beginU32() {
        int at = n;
        u32(0);
        return at;
    }

    public void endU32(int at) {
        long len = n - at - 4;
        for (int i = 0; i < 4; i++) {
            a[at + i] = (byte) (len >>> (8 * i));
        }
    }

    public void putU64(int at, long v) {
        for (int i = 0; i < 8; i++) {
            a[at + i] = (byte) (v >>> (8 * i));
        }
    }
}

