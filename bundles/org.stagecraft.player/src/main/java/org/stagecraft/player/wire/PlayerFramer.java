package org.stagecraft.player.wire;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Splits one direction of a Player connection, delivered in arbitrary chunks, into
 * {@link WireEvent}s. The framer keeps only the bytes of the item it is completing (at most one
 * header or one payload, and payloads are capped at Player's 8 MiB), so a hostile size field can
 * never make it allocate more than the bytes actually received: a payload arriving in pieces is
 * kept as those pieces ({@link #heldBytes()} is exactly what was received) and joined once, when
 * it is complete.
 *
 * <p>On a header that cannot be Player's (bad type, oversize payload, ...) it reports the bytes it
 * skips as {@link WireEvent.Unframed} and scans forward for the next position where a plausible
 * header starts ({@link MessageHeader#plausibleAt}): a few comparisons per byte, no allocation per
 * skipped byte. Not thread-safe: one framer per connection and direction.
 *
 * <p>An observer that cannot afford to hold a large unfinished payload may {@link #abandon} it:
 * the bytes held are released, the rest of that message is passed over as it arrives, and framing
 * continues at the next header; those bytes are counted in {@link #abandonedBytes()}, not reported
 * as events.
 */
public final class PlayerFramer {

    public static final int IDENT_LENGTH = 32;
    private static final byte[] IDENT_PREFIX = "Player v.".getBytes(StandardCharsets.US_ASCII);
    /** Skipped bytes are reported in pieces of at most this size so garbage cannot pile up. */
    private static final int MAX_UNFRAMED_PIECE = 64 * 1024;

    private enum State { BANNER, HEADER, PAYLOAD, DISCARD }

    private final Consumer<? super WireEvent> sink;
    private State state;
    /** Stream offset of the first byte of the item being assembled (or of the next byte). */
    private long itemOffset;
    /** The banner or header being assembled across chunks. */
    private final byte[] head = new byte[MessageHeader.SIZE];
    private int headLength;
    private @Nullable MessageHeader header;
    /** In PAYLOAD: the header's bytes, for reporting the message if it ends unfinished (reused: one per framer). */
    private final byte[] headerBytes = new byte[MessageHeader.SIZE];
    /** The pieces of the payload being assembled, as received. */
    private final List<byte[]> parts = new ArrayList<>();
    private int partsLength;
    /** In DISCARD: payload bytes of an abandoned message still to pass over. */
    private int discardRemaining;

    private @Nullable ByteArrayOutputStream skipped;
    private long skippedOffset;
    private @Nullable String skippedReason;

    private long framedMessages;
    private long unframedBytes;
    private long abandonedBytes;

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
        int end = off + len;
        while (off < end) {
            off = switch (state) {
                case BANNER -> banner(chunk, off, end);
                case HEADER -> header(chunk, off, end);
                case PAYLOAD -> payload(chunk, off, end);
                case DISCARD -> discard(off, end);
            };
        }
    }

    private int banner(byte[] b, int off, int end) {
        if (headLength == 0 && end - off >= IDENT_LENGTH) {
            completeBanner(b, off);
            return off + IDENT_LENGTH;
        }
        int take = Math.min(IDENT_LENGTH - headLength, end - off);
        System.arraycopy(b, off, head, headLength, take);
        headLength += take;
        if (headLength == IDENT_LENGTH) {
            headLength = 0;
            completeBanner(head, 0);
        }
        return off + take;
    }

    private void completeBanner(byte[] b, int off) {
        if (startsWith(b, off, IDENT_PREFIX)) {
            flushSkipped();
            sink.accept(new WireEvent.Banner(itemOffset, Arrays.copyOfRange(b, off, off + IDENT_LENGTH)));
        } else {
            skip(itemOffset, b, off, IDENT_LENGTH, "expected the 32-byte \"Player v.\" ident at the start of the server stream");
        }
        itemOffset += IDENT_LENGTH;
        state = State.HEADER;
    }

    private int header(byte[] b, int off, int end) {
        if (headLength == 0) {
            // Scan the chunk itself: skip every position where no plausible header starts.
            int p = off;
            int last = end - MessageHeader.SIZE;
            while (p <= last && !MessageHeader.plausibleAt(b, p)) {
                p++;
            }
            if (p > off) {
                skipCorrupt(b, off, p);
            }
            if (p <= last) {
                completeHeader(b, p);
                return p + MessageHeader.SIZE;
            }
            // Fewer than a header's bytes left: keep them until the next chunk.
            headLength = end - p;
            System.arraycopy(b, p, head, 0, headLength);
            return end;
        }
        int take = Math.min(MessageHeader.SIZE - headLength, end - off);
        System.arraycopy(b, off, head, headLength, take);
        headLength += take;
        if (headLength < MessageHeader.SIZE) {
            return end;
        }
        if (MessageHeader.plausibleAt(head, 0)) {
            headLength = 0;
            completeHeader(head, 0);
            return off + take;
        }
        // Slide one byte within the assembled header (at most a header's length per chunk boundary).
        skipCorrupt(head, 0, 1);
        headLength--;
        System.arraycopy(head, 1, head, 0, headLength);
        return off + take;
    }

    private void completeHeader(byte[] b, int off) {
        flushSkipped();
        MessageHeader h = MessageHeader.read(b, off);
        if (h.size() == 0) {
            emitFrame(h, new byte[0]);
            itemOffset += MessageHeader.SIZE;
        } else {
            header = h;
            System.arraycopy(b, off, headerBytes, 0, MessageHeader.SIZE);
            state = State.PAYLOAD;
        }
    }

    private int payload(byte[] b, int off, int end) {
        int size = header.size();
        if (partsLength == 0 && end - off >= size) {
            completePayload(Arrays.copyOfRange(b, off, off + size));
            return off + size;
        }
        int take = Math.min(size - partsLength, end - off);
        parts.add(Arrays.copyOfRange(b, off, off + take));
        partsLength += take;
        if (partsLength == size) {
            completePayload(joinParts());
        }
        return off + take;
    }

    private void completePayload(byte[] payload) {
        emitFrame(Objects.requireNonNull(header), payload);
        itemOffset += MessageHeader.SIZE + payload.length;
        header = null;
        state = State.HEADER;
    }

    private byte[] joinParts() {
        byte[] all = new byte[partsLength];
        int at = 0;
        for (byte[] p : parts) {
            System.arraycopy(p, 0, all, at, p.length);
            at += p.length;
        }
        parts.clear();
        partsLength = 0;
        return all;
    }

    private int discard(int off, int end) {
        int take = Math.min(discardRemaining, end - off);
        discardRemaining -= take;
        abandonedBytes += take;
        if (discardRemaining == 0) {
            itemOffset += MessageHeader.SIZE + header.size();
            header = null;
            state = State.HEADER;
        }
        return off + take;
    }

    /**
     * Ends the stream: bytes of an unfinished banner, header or payload are reported as
     * {@link WireEvent.Unframed} so nothing goes missing.
     */
    public void end() {
        if (state == State.PAYLOAD) {
            int got = partsLength;
            byte[] partial = headerAndParts();
            skip(itemOffset, partial, 0, partial.length, "stream ended inside a message: got " + got + " of "
                    + header.size() + " payload bytes");
        } else if (state == State.DISCARD) {
            itemOffset += MessageHeader.SIZE + header.size() - discardRemaining;
            discardRemaining = 0;
        } else if (headLength > 0) {
            int need = state == State.BANNER ? IDENT_LENGTH : MessageHeader.SIZE;
            skip(itemOffset, head, 0, headLength, "stream ended inside a " + (state == State.BANNER ? "banner" : "message header")
                    + ": got " + headLength + " of " + need + " bytes");
        }
        headLength = 0;
        header = null;
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
            byte[] partial = headerAndParts();
            skip(itemOffset, partial, 0, partial.length, "message cut by a gap in observation: " + why);
            itemOffset += partial.length;
        } else if (state == State.DISCARD) {
            itemOffset += MessageHeader.SIZE + header.size() - discardRemaining;
            discardRemaining = 0;
        } else if (headLength > 0) {
            skip(itemOffset, head, 0, headLength, "bytes cut by a gap in observation: " + why);
            itemOffset += headLength;
        }
        flushSkipped();
        headLength = 0;
        header = null;
        itemOffset += lostBytes;
        state = State.HEADER;
    }

    /**
     * Gives up the payload being assembled, if any, to free its memory: the header and the payload
     * bytes held are dropped, and the rest of that message is passed over as it arrives; framing
     * then resumes at the header after it. Returns how many payload bytes were released (0 when no
     * payload was being assembled). Those bytes, and the rest of the message, are counted in
     * {@link #abandonedBytes()}.
     */
    public long abandon() {
        if (state != State.PAYLOAD) {
            return 0;
        }
        long released = partsLength;
        abandonedBytes += MessageHeader.SIZE + partsLength;
        discardRemaining = header.size() - partsLength;
        parts.clear();
        partsLength = 0;
        state = State.DISCARD;
        if (discardRemaining == 0) {
            discard(0, 0);
        }
        return released;
    }

    /** Offset in the stream of the next byte this framer expects. */
    public long nextOffset() {
        return switch (state) {
            case BANNER, HEADER -> itemOffset + headLength;
            case PAYLOAD -> itemOffset + MessageHeader.SIZE + partsLength;
            case DISCARD -> itemOffset + MessageHeader.SIZE + header.size() - discardRemaining;
        };
    }

    /** Stream offset of the message whose payload is being assembled or passed over; -1 if none. */
    public long pendingMessageOffset() {
        return state == State.PAYLOAD || state == State.DISCARD ? itemOffset : -1;
    }

    /** The payload size announced by the message being assembled or passed over; -1 if none. */
    public int pendingMessageSize() {
        return state == State.PAYLOAD || state == State.DISCARD ? header.size() : -1;
    }

    /**
     * Bytes of the stream this framer holds because the item they belong to is not complete yet
     * (a partial banner or header; or a header and the part of its payload received so far).
     */
    public long heldBytes() {
        return headLength + (state == State.PAYLOAD ? MessageHeader.SIZE + partsLength : 0);
    }

    public long framedMessages() {
        return framedMessages;
    }

    public long unframedBytes() {
        return unframedBytes;
    }

    /** Bytes of abandoned messages (header and payload): seen by the framer, never reported. */
    public long abandonedBytes() {
        return abandonedBytes;
    }

    private byte[] headerAndParts() {
        byte[] partial = new byte[MessageHeader.SIZE + partsLength];
        System.arraycopy(headerBytes, 0, partial, 0, MessageHeader.SIZE);
        int at = MessageHeader.SIZE;
        for (byte[] p : parts) {
            System.arraycopy(p, 0, partial, at, p.length);
            at += p.length;
        }
        parts.clear();
        partsLength = 0;
        return partial;
    }

    private void emitFrame(MessageHeader h, byte[] payload) {
        framedMessages++;
        sink.accept(new WireEvent.Frame(itemOffset, h, payload));
    }

    /**
     * Skips b[from..to), each of which starts no plausible header (when 40 bytes follow it), in
     * pieces of at most {@link #MAX_UNFRAMED_PIECE}; a piece's reason names the corrupt header at its
     * first byte.
     */
    private void skipCorrupt(byte[] b, int from, int to) {
        while (from < to) {
            if (skipped == null) {
                String problem = b.length - from >= MessageHeader.SIZE ? MessageHeader.read(b, from).problem() : null;
                startSkip(itemOffset, "corrupt message header at offset " + itemOffset
                        + (problem == null ? "" : ": " + problem));
            }
            int n = Math.min(to - from, MAX_UNFRAMED_PIECE - skipped.size());
            skipped.write(b, from, n);
            unframedBytes += n;
            itemOffset += n;
            from += n;
            if (skipped.size() >= MAX_UNFRAMED_PIECE) {
                flushSkipped();
            }
        }
    }

    private void skip(long offset, byte[] b, int off, int len, String reason) {
        while (len > 0) {
            if (skipped == null) {
                startSkip(offset, reason);
            }
            int n = Math.min(len, MAX_UNFRAMED_PIECE - skipped.size());
            skipped.write(b, off, n);
            unframedBytes += n;
            off += n;
            len -= n;
            offset += n;
            if (skipped.size() >= MAX_UNFRAMED_PIECE) {
                flushSkipped();
            }
        }
    }

    private void startSkip(long offset, String reason) {
        skipped = new ByteArrayOutputStream();
        skippedOffset = offset;
        skippedReason = reason;
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
