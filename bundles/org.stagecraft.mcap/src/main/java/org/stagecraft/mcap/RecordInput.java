package org.stagecraft.mcap;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/** Bounds-checked little-endian reading of one record's content. */
public final class RecordInput {
    private final byte[] a;
    private int p;
    private final int end;

    public RecordInput(byte[] a, int off, int len) {
        this.a = a;
        this.p = off;
        this.end = off + len;
    }

    public int pos() {
        return p;
    }

    public int remaining() {
        return end - p;
    }

    private void need(int k) throws McapFormatException {
        if (k < 0 || k > end - p) {
            throw new McapFormatException("record field runs past its record (" + k + " bytes wanted, "
                    + (end - p) + " left)");
        }
    }

    public int u8() throws McapFormatException {
        need(1);
        return a[p++] & 0xff;
    }

    public int u16() throws McapFormatException {
        need(2);
        int v = (a[p] & 0xff) | (a[p + 1] & 0xff) << 8;
        p += 2;
        return v;
    }

    public long u32() throws McapFormatException {
        need(4);
        long v = 0;
        for (int i = 0; i < 4; i++) {
            v |= (long) (a[p + i] & 0xff) << (8 * i);
        }
        p += 4;
        return v;
    }

    public long u64() throws McapFormatException {
        need(8);
        long v = 0;
        for (int i = 0; i < 8; i++) {
            v |= (long) (a[p + i] & 0xff) << (8 * i);
        }
        p += 8;
        return v;
    }

    public int length32() throws McapFormatException {
        long len = u32();
        if (len > end - p) {
            throw new McapFormatException("length " + len + " runs past its record");
        }
        return (int) len;
    }

    public String string() throws McapFormatException {
        int len = length32();
        String s = new String(a, p, len, StandardCharsets.UTF_8);
        p += len;
        return s;
    }

    public byte[] bytes(int len) throws McapFormatException {
        need(len);
        byte[] b = Arrays.copyOfRange(a, p, p + len);
        p += len;
        return b;
    }

    public void skip(int len) throws McapFormatException {
        need(len);
        p += len;
    }

    public byte[] array() {
        return a;
    }
}

