package org.stagecraft.mcap;

import java.util.Arrays;

import org.eclipse.jdt.annotation.Nullable;

/**
 * MCAP (https://mcap.dev, major version 0): the magic bytes and the record opcodes, from the
 * specification.
 */
public final class Mcap {
    private Mcap() {
    }

    public static final byte[] MAGIC = { (byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n' };

    public static final int OP_HEADER = 0x01;
    public static final int OP_FOOTER = 0x02;
    public static final int OP_SCHEMA = 0x03;
    public static final int OP_CHANNEL = 0x04;
    public static final int OP_MESSAGE = 0x05;
    public static final int OP_CHUNK = 0x06;
    public static final int OP_MESSAGE_INDEX = 0x07;
    public static final int OP_CHUNK_INDEX = 0x08;
    public static final int OP_ATTACHMENT = 0x09;
    public static final int OP_ATTACHMENT_INDEX = 0x0A;
    public static final int OP_STATISTICS = 0x0B;
    public static final int OP_METADATA = 0x0C;
    public static final int OP_METADATA_INDEX = 0x0D;
    public static final int OP_SUMMARY_OFFSET = 0x0E;
    public static final int OP_DATA_END = 0x0F;

    /** opcode (1) + content length (8) */
    public static final int RECORD_PREFIX = 9;
    /** Footer content: summary_start, summary_offset_start, summary_crc. */
    static final int FOOTER_CONTENT = 8 + 8 + 4;
    /** Footer record + trailing magic. */
    static final int TAIL = RECORD_PREFIX + FOOTER_CONTENT + 8;
    /** A chunk record's content before its records: start, end, uncompressed size, CRC, compression length, records length. */
    static final int CHUNK_FIXED = 8 + 8 + 8 + 4 + 4 + 8;

    /** True if {@code head} starts with MCAP's magic bytes. */
    public static boolean isMcap(byte[] head) {
        return head.length >= MAGIC.length && Arrays.equals(head, 0, MAGIC.length, MAGIC, 0, MAGIC.length);
    }

    /**
     * Why a file starting with {@code head} (its first bytes, or all of a shorter file) is not MCAP,
     * for people, e.g. "it is empty (0 bytes)"; null when it starts with the magic.
     */
    public static @Nullable String whyNotMcap(byte[] head) {
        if (isMcap(head)) {
            return null;
        }
        if (head.length == 0) {
            return "it is empty (0 bytes)";
        }
        if (head.length < MAGIC.length) {
            return "it has only " + head.length + " byte" + (head.length == 1 ? "" : "s") + ", fewer than MCAP's "
                    + MAGIC.length + "-byte magic";
        }
        return "it does not start with MCAP's magic bytes (" + hex(MAGIC) + ") but with " + hex(Arrays.copyOf(head, MAGIC.length));
    }

    private static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(s.isEmpty() ? "" : " ").append(Character.forDigit((x >> 4) & 0xf, 16)).append(Character.forDigit(x & 0xf, 16));
        }
        return s.toString();
    }

    static long u64(byte[] a, int at) {
        long v = 0;
        for (int i = 0; i < 8; i++) {
            v |= (long) (a[at + i] & 0xff) << (8 * i);
        }
        return v;
    }

    static long u32(byte[] a, int at) {
        long v = 0;
        for (int i = 0; i < 4; i++) {
            v |= (long) (a[at + i] & 0xff) << (8 * i);
        }
        return v;
    }
}
