package org.stagecraft.player.wire;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.function.Consumer;

/**
 * Splits one direction of a Player connection, delivered in arbitrary chunks, into
 * {@link WireEvent}s. The framer keeps only the bytes of the item it is completing (at most one
 * header or one payload, and payloads are capped at Player's 8 MiB), so a hostile size field can
 * never make it allocate more than the bytes actually received.
 *
 * <p>On a header that cannot be Player's (bad type, oversize payload, ...) it reports the bytes it
 * skips as {@link WireEvent.Unframed} and slides forward one byte at a time until a plausible
 * header starts. Not thread-safe: one framer per connection and direction.
 */
public final class PlayerFramer {

    public static final int IDENT_LENGTH = 32;
    private static final byte[] IDENT_PREFIX = "Player v.".getBytes(StandardCharsets.US_ASCII);
    /** Skipped bytes are reported in pieces of at most this size so garbage cannot pile up. */
    private static final int MAX_UNFRAMED_PIECE = 64 * 1024;

    private enum State { BANNER, HEADER, PAYLOAD }

    private final Consumer<? super WireEvent> sink;
    private State state;
    /** Stream offset of the first byte of the item being assembled (or of the next byte). */
    private long itemOffset;
    private byte[] pending = new byte[64];
    private int pendingLength;
    private MessageHeader header;
    private byte[] headerBytes;

    private ByteArrayOutputStream skipped;
    private long skippedOffset;
    private String skippedReason;

    private long framedMessages;
    private long unframedBytes;

    /**
     * @param direction which way the bytes flow; server-to-client streams begin with the ident
     * @param sink      receives events in stream order, on the caller's thread
     */
    public PlayerFramer(Direction direction, Consumer<? super WireEvent> sink) {
        this.sink = sink;
        this.state = direction == Direction.SERVER_TO_CLIENT ? State.BANNER : State.HEADER;
    }

    public void accept(byte[] chunk) {
        accept(chunk, 0, chunk.length);
    }

    /** Feeds the next bytes of the stream; the array is not kept. */
    public void accept(byte[] chunk, int off, int len) {
        while (true) {
            int need = bytesNeeded();
            if (pendingLength == 0) {
                if (need == 0 || len >= need) {
                    int used = complete(chunk, off);
                    off += used;
                    len -= used;
                    continue;
                }
                if (len == 0) {
                    return;
                }
            }
            int take = Math.min(need - pendingLength, len);
            if (take > 0) {
                ensurePending(pendingLength + take);
                System.arraycopy(chunk, off, pending, pendingLength, take);
                pendingLength += take;
                off += take;
                len -= take;
            }
            if (pendingLength < need) {
                return;
            }
            int used = complete(pending, 0);
            pendingLength -= used;
            System.arraycopy(pending, used, pending, 0, pendingLength);
        }
    }

    /**
     * Ends the stream: bytes of an unfinished banner, header or payload are reported as
     * {@link WireEvent.Unframed} so nothing goes missing.
     */
    public void end() {
        if (state == State.PAYLOAD) {
            byte[] partial = new byte[MessageHeader.SIZE + pendingLength];
            System.arraycopy(headerBytes, 0, partial, 0, MessageHeader.SIZE);
            System.arraycopy(pending, 0, partial, MessageHeader.SIZE, pendingLength);
            skip(itemOffset, partial, 0, partial.length, "stream ended inside a message: got " + pendingLength + " of "
                    + header.size() + " payload bytes");
        } else if (pendingLength > 0) {
            skip(itemOffset, pending, 0, pendingLength, "stream ended inside a " + (state == State.BANNER ? "banner" : "message header")
                    + ": got " + pendingLength + " of " + bytesNeeded() + " bytes");
        }
        pendingLength = 0;
        flushSkipped();
        state = State.HEADER;
    }

    /**
     * Some bytes of the stream were never seen by this framer (an observer fell behind and had to
     * drop them). What was being assembled is reported as unframed, the offset moves past the gap,
     * and framing resumes by looking for the next plausible header.
     */
    public void gap(long lostBytes, String why) {
        if (lostBytes <= 0) {
            return;
        }
        if (state == State.PAYLOAD) {
            byte[] partial = new byte[MessageHeader.SIZE + pendingLength];
            System.arraycopy(headerBytes, 0, partial, 0, MessageHeader.SIZE);
            System.arraycopy(pending, 0, partial, MessageHeader.SIZE, pendingLength);
            skip(itemOffset, partial, 0, partial.length, "message cut by a gap in observation: " + why);
            itemOffset += partial.length;
        } else if (pendingLength > 0) {
            skip(itemOffset, pending, 0, pendingLength, "bytes cut by a gap in observation: " + why);
            itemOffset += pendingLength;
        }
        flushSkipped();
        pendingLength = 0;
        header = null;
        headerBytes = null;
        itemOffset += lostBytes;
        state = State.HEADER;
    }

    /** Offset in the stream of the next byte this framer expects. */
    public long nextOffset() {
        return itemOffset + pendingLength + (state == State.PAYLOAD ? MessageHeader.SIZE : 0);
    }

    public long framedMessages() {
        return framedMessages;
    }

    public long unframedBytes() {
        return unframedBytes;
    }

    private int bytesNeeded() {
        return switch (state) {
            case BANNER -> IDENT_LENGTH;
            case HEADER -> MessageHeader.SIZE;
            case PAYLOAD -> header.size();
        };
    }

    private void ensurePending(int capacity) {
        if (pending.length < capacity) {
            pending = Arrays.copyOf(pending, Math.max(capacity, pending.length * 2));
        }
    }

    /** Consumes a complete item starting at b[off]; returns how many bytes it used. */
    private int complete(byte[] b, int off) {
        switch (state) {
            case BANNER -> {
                if (startsWith(b, off, IDENT_PREFIX)) {
                    flushSkipped();
                    sink.accept(new WireEvent.Banner(itemOffset, Arrays.copyOfRange(b, off, off + IDENT_LENGTH)));
                } else {
                    skip(itemOffset, b, off, IDENT_LENGTH, "expected the 32-byte \"Player v.\" ident at the start of the server stream");
                }
                itemOffset += IDENT_LENGTH;
                state = State.HEADER;
                return IDENT_LENGTH;
            }
            case HEADER -> {
                MessageHeader h = MessageHeader.read(b, off);
                String problem = h.problem();
                if (problem != null) {
                    // Slide one byte and look for the next plausible header.
                    skip(itemOffset, b, off, 1, "corrupt message header at offset " + itemOffset + ": " + problem);
                    itemOffset += 1;
                    return 1;
                }
                flushSkipped();
                if (h.size() == 0) {
                    emitFrame(h, new byte[0]);
                    itemOffset += MessageHeader.SIZE;
                } else {
                    header = h;
                    headerBytes = Arrays.copyOfRange(b, off, off + MessageHeader.SIZE);
                    state = State.PAYLOAD;
                }
                return MessageHeader.SIZE;
            }
            case PAYLOAD -> {
                int n = header.size();
                emitFrame(header, Arrays.copyOfRange(b, off, off + n));
                itemOffset += MessageHeader.SIZE + n;
                header = null;
                headerBytes = null;
                state = State.HEADER;
                return n;
            }
            default -> throw new IllegalStateException(state.toString());
        }
    }

    private void emitFrame(MessageHeader h, byte[] payload) {
        framedMessages++;
        sink.accept(new WireEvent.Frame(itemOffset, h, payload));
    }

    private void skip(long offset, byte[] b, int off, int len, String reason) {
        if (skipped == null) {
            skipped = new ByteArrayOutputStream();
            skippedOffset = offset;
            skippedReason = reason;
        }
        skipped.write(b, off, len);
        unframedBytes += len;
        if (skipped.size() >= MAX_UNFRAMED_PIECE) {
            flushSkipped();
        }
    }

    private void flushSkipped() {
        if (skipped == null) {
            return;
        }
        sink.accept(new WireEvent.Unframed(skippedOffset, skipped.toByteArray(),
                skippedReason + "; " + skipped.size() + " bytes skipped"));
        skipped = null;
        skippedReason = null;
    }

    private static boolean startsWith(byte[] b, int off, byte[] prefix) {
        for (int i = 0; i < prefix.length; i++) {
            if (b[off + i] != prefix[i]) {
                return false;
            }
        }
        return true;
    }
}
