package org.stagecraft.spy.hold;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;

/**
 * Follows the message boundaries of a program-to-Player stream however it is chunked: collects each
 * 40-byte header, then counts its payload bytes. The stream from a client has no banner, so it starts
 * on a boundary. It never copies payloads and never delays a byte itself: the caller decides what to
 * do with each span of bytes it hands over.
 *
 * <p>If a header is not a Player header (see {@link MessageHeader#problem()}), boundaries are lost for
 * good: a relay cannot resynchronise without guessing, and a guess could inject into the middle of a
 * message. From then on {@link #lost()} is true and every span is {@link Part#UNKNOWN}.
 */
final class BoundaryTracker {
    enum Part {
        HEADER, PAYLOAD, UNKNOWN
    }

    /** {@link #advance} results, as bit flags. */
    static final int HEADER_DONE = 1;
    static final int MESSAGE_DONE = 2;
    static final int LOST = 4;

    private final byte[] header = new byte[MessageHeader.SIZE];
    private int headerFill;
    private long payloadLeft;
    private long offset;
    private long messageStart;
    private int interf;
    private int type;
    /** Made from the header bytes only when asked for: most messages need just interface and type. */
    private @Nullable MessageHeader current;
    private @Nullable String lostReason;

    Part part() {
        if (lostReason != null) {
            return Part.UNKNOWN;
        }
        return payloadLeft > 0 ? Part.PAYLOAD : Part.HEADER;
    }

    /** Between two messages (or before the first): the only place bytes may be injected. */
    boolean atBoundary() {
        return lostReason == null && payloadLeft == 0 && headerFill == 0;
    }

    boolean lost() {
        return lostReason != null;
    }

    /** Why boundaries were lost, or null. */
    @Nullable String lostReason() {
        return lostReason;
    }

    /** Bytes of the stream consumed so far. */
    long offset() {
        return offset;
    }

    /** Stream offset of the current (or last) message's first byte. */
    long messageStart() {
        return messageStart;
    }

    int headerFill() {
        return headerFill;
    }

    /**
     * The header bytes collected so far: part of a header while it comes in, all 40 right after
     * {@link #HEADER_DONE} or {@link #LOST} (until the next message's first byte).
     */
    byte[] headerBytes() {
        return java.util.Arrays.copyOf(header, headerFill == 0 ? MessageHeader.SIZE : headerFill);
    }

    /** The current message's header, once {@link #HEADER_DONE} was returned for it (until the next begins). */
    MessageHeader header() {
        MessageHeader c = current;
        if (c == null) {
            c = MessageHeader.read(header, 0);
            current = c;
        }
        return c;
    }

    /** The current message's interface code (valid like {@link #header()}). */
    int interf() {
        return interf;
    }

    /** The current message's type code (valid like {@link #header()}). */
    int type() {
        return type;
    }

    private int word(int at) {
        return (header[at] & 0xff) << 24 | (header[at + 1] & 0xff) << 16 | (header[at + 2] & 0xff) << 8 | (header[at + 3] & 0xff);
    }

    /** How many of the next {@code available} bytes belong to the current part. */
    int span(int available) {
        return switch (part()) {
            case HEADER -> Math.min(available, MessageHeader.SIZE - headerFill);
            case PAYLOAD -> (int) Math.min(available, payloadLeft);
            case UNKNOWN -> available;
        };
    }

    /**
     * Consumes {@code n <= span(...)} bytes of the current part.
     *
     * @return flags: {@link #HEADER_DONE} (header() is the new message's), {@link #MESSAGE_DONE} (back
     *         on a boundary), {@link #LOST}
     */
    int advance(byte[] buf, int off, int n) {
        switch (part()) {
            case UNKNOWN -> {
                offset += n;
                return 0;
            }
            case PAYLOAD -> {
                payloadLeft -= n;
                offset += n;
                return payloadLeft == 0 ? MESSAGE_DONE : 0;
            }
            default -> {
                if (headerFill == 0) {
                    messageStart = offset;
                    current = null;
                }
                System.arraycopy(buf, off, header, headerFill, n);
                headerFill += n;
                offset += n;
                if (headerFill < MessageHeader.SIZE) {
                    return 0;
                }
                // the checks of MessageHeader.problem(), without making a header object per message
                interf = word(8);
                int index = word(12);
                type = word(16);
                int subtype = word(20);
                int size = word(36);
                if (type < 1 || type > 6 || (interf & 0xFFFF0000) != 0 || (index & 0xFFFF0000) != 0
                        || (subtype & 0xFFFFFF00) != 0 || size < 0 || size > MessageHeader.MAX_PAYLOAD) {
                    lostReason = "not a Player message at offset " + messageStart + ": "
                            + MessageHeader.read(header, 0).problem();
                    return LOST;
                }
                headerFill = 0;
                payloadLeft = size;
                return payloadLeft == 0 ? HEADER_DONE | MESSAGE_DONE : HEADER_DONE;
            }
        }
    }
}
