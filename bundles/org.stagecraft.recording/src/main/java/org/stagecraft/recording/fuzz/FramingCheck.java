package org.stagecraft.recording.fuzz;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.zip.CRC32;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.session.SessionFramer;
import org.stagecraft.player.session.StreamId;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceFormatException;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/**
 * Reads one (possibly hostile) trace the way {@code stagecraft decode} does — trace reader,
 * {@link SessionFramer}, {@link PlayerDecoder} — and checks what must hold whatever the input:
 * <ul>
 * <li>every byte of every stream is reported by exactly one event, in order (event offsets are
 * contiguous, and the CRC and count of the reported bytes equal those of the bytes fed);</li>
 * <li>the session framer (which parks idle directions) reports exactly what one plain
 * {@link PlayerFramer} per direction reports;</li>
 * <li>a bad file is refused with a {@link TraceFormatException}, never an unchecked exception.</li>
 * </ul>
 * An unchecked exception from any part propagates to the caller; a broken invariant throws
 * {@link Violation}.
 */
public final class FramingCheck {
    /** An invariant did not hold. */
    public static final class Violation extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Violation(String message) {
            super(message);
        }
    }

    /** What reading one variant gave. {@code refusal} is the reader's message, or null if the file was read whole. */
    public record Outcome(long records, long chunkBytes, long events, long frames, long unframedBytes, long banners,
            long decodeProblems, @Nullable String refusal) {
    }

    private final PlayerDecoder decoder;

    public FramingCheck(PlayerDecoder decoder) {
        this.decoder = decoder;
    }

    /** Per stream: what was fed, what was reported, and the plain framer's events still to be matched. */
    private static final class Ledger {
        final CRC32 fed = new CRC32();
        final CRC32 reported = new CRC32();
        long fedBytes;
        long reportedBytes;
        final ArrayDeque<WireEvent> plain = new ArrayDeque<>();
        @Nullable PlayerFramer plainFramer;
    }

    public Outcome check(String name, byte[] file) {
        Map<StreamId, Ledger> ledgers = new HashMap<>();
        long[] n = new long[6]; // records, events, frames, unframed bytes, banners, decode problems
        long chunkBytes = 0;
        String refusal = null;
        SessionFramer framer = new SessionFramer(e -> {
            n[1]++;
            @Nullable Ledger l = ledgers.get(e.stream());
            if (l == null) {
                throw new Violation(e.stream() + ": an event for a stream that was never fed: " + e.event());
            }
            account(l, e);
            switch (e.event()) {
                case WireEvent.Banner b -> n[4]++;
                case WireEvent.Unframed u -> n[3] += u.length();
                case WireEvent.Frame f -> {
                    n[2]++;
                    if (decoder.decode(f).hasProblem()) {
                        n[5]++;
                    }
                }
            }
        });
        double last = 0;
        try (TraceReader reader = new TraceReader(name, new ByteArrayInputStream(file))) {
            for (TraceRecord r = reader.next(); r != null; r = reader.next()) {
                n[0]++;
                switch (r) {
                    case TraceRecord.Header h -> {
                    }
                    case TraceRecord.Chunk c -> {
                        last = c.t();
                        Ledger l = ledgers.computeIfAbsent(c.stream(), s -> new Ledger());
                        l.fed.update(c.data());
                        l.fedBytes += c.data().length;
                        chunkBytes += c.data().length;
                        if (l.plainFramer == null) {
                            l.plainFramer = new PlayerFramer(c.stream().dir(), l.plain::add);
                        }
                        l.plainFramer.accept(c.data());
                        framer.chunk(c.t(), c.stream(), c.data());
                    }
                    case TraceRecord.Lifecycle lc -> {
                        last = lc.t();
                        if (lc.isClose()) {
                            ledgers.forEach((s, l) -> {
                                if (s.conn() == lc.conn() && l.plainFramer != null) {
                                    l.plainFramer.end();
                                    l.plainFramer = null;
                                }
                            });
                            framer.close(lc.t(), lc.conn());
                            // a later chunk of the same number is a new connection: its streams start at 0
                            ledgers.entrySet().removeIf(en -> en.getKey().conn() == lc.conn() && settled(en.getKey(), en.getValue()));
                        }
                    }
                }
            }
        } catch (TraceFormatException e) {
            refusal = e.getMessage();
        } catch (IOException e) {
            throw new Violation("reading from memory failed: " + e);
        }
        for (Ledger l : ledgers.values()) {
            if (l.plainFramer != null) {
                l.plainFramer.end();
                l.plainFramer = null;
            }
        }
        framer.endAll(last);
        if (framer.openConnections() != 0 || framer.activeFramers() != 0) {
            throw new Violation("the session framer still holds " + framer.openConnections() + " connections after the end");
        }
        ledgers.forEach(FramingCheck::settled);
        return new Outcome(n[0], chunkBytes, n[1], n[2], n[3], n[4], n[5], refusal);
    }

    /** Checks a stream that has ended: every byte fed was reported, and both framers agree; returns true. */
    private static boolean settled(StreamId stream, Ledger l) {
        if (l.fedBytes != l.reportedBytes || l.fed.getValue() != l.reported.getValue()) {
            throw new Violation(stream + ": " + l.fedBytes + " bytes fed, " + l.reportedBytes + " reported (or not the same bytes)");
        }
        if (!l.plain.isEmpty()) {
            throw new Violation(stream + ": the plain framer reported " + l.plain.size()
                    + " more events than the session framer, first " + describe(l.plain.peek()));
        }
        return true;
    }

    private static void account(Ledger l, SessionEvent e) {
        WireEvent w = e.event();
        if (w.offset() != l.reportedBytes) {
            throw new Violation(e.stream() + ": event at offset " + w.offset() + " but " + l.reportedBytes
                    + " bytes were reported before it: " + w);
        }
        byte[] bytes = w.bytes();
        l.reported.update(bytes);
        l.reportedBytes += bytes.length;
        @Nullable WireEvent expected = l.plain.poll();
        if (expected == null || !same(expected, w)) {
            throw new Violation(e.stream() + ": the session framer reported " + describe(w) + " where one framer for the stream reported "
                    + (expected == null ? "nothing" : describe(expected)));
        }
    }

    private static boolean same(WireEvent a, WireEvent b) {
        if (a.getClass() != b.getClass() || a.offset() != b.offset() || !Arrays.equals(a.bytes(), b.bytes())) {
            return false;
        }
        return !(a instanceof WireEvent.Unframed ua) || ua.reason().equals(((WireEvent.Unframed) b).reason());
    }

    private static String describe(WireEvent e) {
        return switch (e) {
            case WireEvent.Banner b -> "a banner at " + b.offset();
            case WireEvent.Frame f -> "a message of " + f.wireSize() + " bytes at " + f.offset();
            case WireEvent.Unframed u -> u.length() + " unframed bytes at " + u.offset() + " (" + u.reason() + ")";
        };
    }
}
