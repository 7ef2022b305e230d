package org.stagecraft.spy.hold;

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
    private MessageHeader current;
    private String lostReason;

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
    String lostReason() {
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

    /** The current message's header, once {@link #HEADER_DONE} was returned for it. */
    MessageHeader header() {
        return current;
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
                }
                System.arraycopy(buf, off, header, headerFill, n);
                headerFill += n;
                offset += n;
                if (headerFill < MessageHeader.SIZE) {
                    return 0;
                }
                MessageHeader h = MessageHeader.read(header, 0);
                String problem = h.problem();
                if (problem != null) {
                    lostReason = "not a Player message at offset " + messageStart + ": " + problem;
                    return LOST;
                }
                current = h;
                headerFill = 0;
                payloadLeft = h.sizeUnsigned();
                return payloadLeft == 0 ? HEADER_DONE | MESSAGE_DONE : HEADER_DONE;
            }
        }
    }
}
