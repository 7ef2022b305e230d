package org.stagecraft.player.wire;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/**
 * The 40-byte Player message header (struct player_msghdr). Every word is kept exactly as it was
 * on the wire, so a header re-encodes byte for byte even when a field holds garbage (SYNCH
 * timestamps and sequence numbers are uninitialised memory in real Player).
 *
 * @param host      u32; server to client: the server's IPv4 address as Player stored it
 * @param robot     u32; server to client: the TCP port of the Player server socket
 * @param interf    interface code (u16 on the wire in a 4-byte word)
 * @param index     device index (u16)
 * @param type      message type code, see {@link MessageType}
 * @param subtype   interface-specific subtype (u8)
 * @param timestamp seconds (simulation time from Stage, wall clock from clients)
 * @param seq       u32 sequence number
 * @param size      number of XDR payload bytes that follow
 */
public record MessageHeader(int host, int robot, int interf, int index, int type, int subtype, double timestamp,
        int seq, int size) {

    public static final int SIZE = 40;

    /** PLAYER_MAX_MESSAGE_SIZE: the largest payload Player accepts. */
    public static final int MAX_PAYLOAD = 8 * 1024 * 1024;

    public static MessageHeader read(XdrReader r) {
        return new MessageHeader(r.int32(), r.int32(), r.int32(), r.int32(), r.int32(), r.int32(), r.float64(),
                r.int32(), r.int32());
    }

    public static MessageHeader read(byte[] b, int off) {
        return read(new XdrReader(b, off, SIZE));
    }

    public void write(XdrWriter w) {
        w.int32(host).int32(robot).int32(interf).int32(index).int32(type).int32(subtype).float64(timestamp)
                .int32(seq).int32(size);
    }

    public @Nullable MessageType messageType() {
        return MessageType.of(type);
    }

    public MessageHeader withSize(int newSize) {
        return new MessageHeader(host, robot, interf, index, type, subtype, timestamp, seq, newSize);
    }

    public long hostUnsigned() {
        return Integer.toUnsignedLong(host);
    }

    public long robotUnsigned() {
        return Integer.toUnsignedLong(robot);
    }

    public long seqUnsigned() {
        return Integer.toUnsignedLong(seq);
    }

    public long sizeUnsigned() {
        return Integer.toUnsignedLong(size);
    }

    /**
     * Whether the {@link #SIZE} bytes at {@code b[off]} can be a Player message header: the same
     * checks as {@link #problem()} (type 1..6, interface and index within 16 bits, subtype within 8,
     * payload size 0..{@link #MAX_PAYLOAD}), read in place without creating anything, so that a
     * framer can scan garbage for the next header at memory speed.
     */
    public static boolean plausibleAt(byte[] b, int off) {
        int type = word(b, off + 16);
        if (type < 1 || type > 6) {
            return false;
        }
        if ((word(b, off + 8) & 0xFFFF0000) != 0 || (word(b, off + 12) & 0xFFFF0000) != 0
                || (word(b, off + 20) & 0xFFFFFF00) != 0) {
            return false;
        }
        int size = word(b, off + 36);
        return size >= 0 && size <= MAX_PAYLOAD;
    }

    private static int word(byte[] b, int off) {
        return (b[off] & 0xFF) << 24 | (b[off + 1] & 0xFF) << 16 | (b[off + 2] & 0xFF) << 8 | (b[off + 3] & 0xFF);
    }

    /**
     * Why this header cannot be a Player message header, or null if it can. Host, robot, timestamp
     * and seq are never checked: real servers leave them uninitialised on some messages.
     */
    public @Nullable String problem() {
        if (MessageType.of(type) == null) {
            return "message type " + Integer.toUnsignedLong(type) + " is not a Player message type (1..6)";
        }
        if ((interf & 0xFFFF0000) != 0) {
            return "interface word 0x" + Integer.toHexString(interf) + " exceeds 16 bits";
        }
        if ((index & 0xFFFF0000) != 0) {
            return "index word 0x" + Integer.toHexString(index) + " exceeds 16 bits";
        }
        if ((subtype & 0xFFFFFF00) != 0) {
            return "subtype word 0x" + Integer.toHexString(subtype) + " exceeds 8 bits";
        }
        if (size < 0 || size > MAX_PAYLOAD) {
            return "payload size " + Integer.toUnsignedLong(size) + " exceeds Player's limit of " + MAX_PAYLOAD
                    + " bytes";
        }
        return null;
    }
}
