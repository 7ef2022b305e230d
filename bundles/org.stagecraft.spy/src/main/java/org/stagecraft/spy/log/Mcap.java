package org.stagecraft.spy.log;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * MCAP (https://mcap.dev, major version 0) constants and the little-endian record encoding, written
 * from the specification. Package-private: the public face is {@link SpyLogWriter} and
 * {@link SpyLogReader}.
 */
final class Mcap {
    private Mcap() {
    }

    static final byte[] MAGIC = { (byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n' };

    static final int OP_HEADER = 0x01;
    static final int OP_FOOTER = 0x02;
    static final int OP_SCHEMA = 0x03;
    static final int OP_CHANNEL = 0x04;
    static final int OP_MESSAGE = 0x05;
    static final int OP_CHUNK = 0x06;
    static final int OP_MESSAGE_INDEX = 0x07;
    static final int OP_CHUNK_INDEX = 0x08;
    static final int OP_STATISTICS = 0x0B;
    static final int OP_METADATA = 0x0C;
    static final int OP_METADATA_INDEX = 0x0D;
    static final int OP_SUMMARY_OFFSET = 0x0E;
    static final int OP_DATA_END = 0x0F;

    /** opcode (1) + content length (8) */
    static final int RECORD_PREFIX = 9;
    /** Footer content: summary_start, summary_offset_start, summary_crc. */
    static final int FOOTER_CONTENT = 8 + 8 + 4;
    /** Footer record + trailing magic. */
    static final int TAIL = RECORD_PREFIX + FOOTER_CONTENT + 8;

    /** A growable little-endian byte buffer. */
    static final class Buf {
        private byte[] a;
        private int n;

        Buf(int capacity) {
            a = new byte[Math.max(16, capacity)];
        }

        int size() {
            return n;
        }

        byte[] array() {
            return a;
        }

        void clear() {
            n = 0;
        }

        byte[] toByteArray() {
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

        Buf u8(int v) {
            room(1);
            a[n++] = (byte) v;
            return this;
        }

        Buf u16(int v) {
            room(2);
            a[n++] = (byte) v;
            a[n++] = (byte) (v >>> 8);
            return this;
        }

        Buf u32(long v) {
            room(4);
            for (int i = 0; i < 4; i++) {
                a[n++] = (byte) (v >>> (8 * i));
            }
            return this;
        }

        Buf u64(long v) {
            room(8);
            for (int i = 0; i < 8; i++) {
                a[n++] = (byte) (v >>> (8 * i));
            }
            return this;
        }

        Buf bytes(byte[] b, int off, int len) {
            room(len);
            System.arraycopy(b, off, a, n, len);
            n += len;
            return this;
        }

        Buf bytes(byte[] b) {
            return bytes(b, 0, b.length);
        }

        Buf string(String s) {
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            u32(b.length);
            return bytes(b);
        }

        /** Starts a record: opcode and a length placeholder; returns the position to pass to {@link #end}. */
        int begin(int opcode) {
            u8(opcode);
            int at = n;
            u64(0);
            return at;
        }

        /** Patches the content length of the record begun at {@code at}. */
        void end(int at) {
            putU64(at, n - at - 8);
        }

        /** Starts a u32 byte-length prefix (Map, Array); returns the position for {@link #endU32}. */
        int beginU32() {
            int at = n;
            u32(0);
            return at;
        }

        void endU32(int at) {
            long len = n - at - 4;
            for (int i = 0; i < 4; i++) {
                a[at + i] = (byte) (len >>> (8 * i));
            }
        }

        void putU64(int at, long v) {
            for (int i = 0; i < 8; i++) {
                a[at + i] = (byte) (v >>> (8 * i));
            }
        }
    }

    /** Bounds-checked little-endian reading of one record's content. */
    static final class In {
        private final byte[] a;
        private int p;
        private final int end;

        In(byte[] a, int off, int len) {
            this.a = a;
            this.p = off;
            this.end = off + len;
        }

        int pos() {
            return p;
        }

        int remaining() {
            return end - p;
        }

        private void need(int k) throws SpyLogFormatException {
            if (k < 0 || k > end - p) {
                throw new SpyLogFormatException("record field runs past its record (" + k + " bytes wanted, "
                        + (end - p) + " left)");
            }
        }

        int u8() throws SpyLogFormatException {
            need(1);
            return a[p++] & 0xff;
        }

        int u16() throws SpyLogFormatException {
            need(2);
            int v = (a[p] & 0xff) | (a[p + 1] & 0xff) << 8;
            p += 2;
            return v;
        }

        long u32() throws SpyLogFormatException {
            need(4);
            long v = 0;
            for (int i = 0; i < 4; i++) {
                v |= (long) (a[p + i] & 0xff) << (8 * i);
            }
            p += 4;
            return v;
        }

        long u64() throws SpyLogFormatException {
            need(8);
            long v = 0;
            for (int i = 0; i < 8; i++) {
                v |= (long) (a[p + i] & 0xff) << (8 * i);
            }
            p += 8;
            return v;
        }

        int length32() throws SpyLogFormatException {
            long len = u32();
            if (len > end - p) {
                throw new SpyLogFormatException("length " + len + " runs past its record");
            }
            return (int) len;
        }

        String string() throws SpyLogFormatException {
            int len = length32();
            String s = new String(a, p, len, StandardCharsets.UTF_8);
            p += len;
            return s;
        }

        byte[] bytes(int len) throws SpyLogFormatException {
            need(len);
            byte[] b = Arrays.copyOfRange(a, p, p + len);
            p += len;
            return b;
        }

        void skip(int len) throws SpyLogFormatException {
            need(len);
            p += len;
        }

        byte[] array() {
            return a;
        }
    }

    static long readU64(byte[] a, int at) {
        long v = 0;
        for (int i = 0; i < 8; i++) {
            v |= (long) (a[at + i] & 0xff) << (8 * i);
        }
        return v;
    }
}
