package org.stagecraft.replay.log;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.time.Instant;
import java.time.OffsetDateTime;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.stagecraft.recording.trace.TraceFormatException;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * Writes a recorded trace ({@code *.trace.jsonl}) into a spy log the way the spy would have logged
 * the same traffic: the chunks framed per connection and direction, every banner, message and piece
 * of unframed bytes at the time of the chunk that completed it, connections opened and closed. A
 * trace that stops being readable (a bad line, a cut-off file) is imported up to that line, and the
 * problem says which line.
 *
 * <p>A trace's times are seconds since its recorder started; its header says when that was
 * ({@code "created"}, an ISO-8601 date). The log gets wall-clock times, the creation date plus the
 * trace's time, as the spy's own logs have: exports then carry the real date of the capture.
 * Without a readable date the trace's own times are kept (they then start near 1970).
 */
final class TraceImport {
    private TraceImport() {
    }

    /** The robot program's address in an imported trace, as the demo and the views' replays name it. */
    static String clientAddress(int conn) {
        return "127.0.0.1:" + (40000 + conn);
    }

    static String playerAddress(int port) {
        return "127.0.0.1:" + port;
    }

    /** @return what could not be read (empty when the whole trace went in) */
    static List<LogProblem> convert(Path trace, SpyLogWriter out) throws IOException {
        List<LogProblem> problems = new ArrayList<>();
        long start = startNanos(trace);
        long[] last = { 0 };
        try (TraceReader reader = new TraceReader(trace)) {
            try {
                TraceFraming.frame(reader, e -> {
                    last[0] = start + nanos(e.t());
                    write(() -> out.wire(start + nanos(e.t()), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event()));
                }, l -> {
                    last[0] = start + nanos(l.t());
                    write(() -> {
                        if (l.isClose()) {
                            out.connectionClosed(start + nanos(l.t()), l.conn(), "closed (recorded)");
                        } else {
                            out.connectionOpened(start + nanos(l.t()), l.conn(), clientAddress(l.conn()), playerAddress(l.port()),
                                    playerAddress(l.port()));
                        }
                    });
                });
            } catch (TraceFormatException e) {
                problems.add(new LogProblem(e.line() > 0 ? "line " + e.line() : "file", last[0],
                        e.reason() + (e.line() > 1 ? "; the trace is read up to the line before" : "")));
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        }
        return problems;
    }

    private interface LogWrite {
        void run() throws IOException;
    }

    private static void write(LogWrite w) {
        try {
            w.run();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static Map<String, String> metadata(Path trace) {
        return Map.of("imported-from", trace.toString(), "format", "player-trace");
    }

    /** When the trace's recorder started, from the header's "created" date; 0 when it has none. */
    static long startNanos(Path trace) throws IOException {
        try (TraceReader reader = new TraceReader(trace)) {
            if (reader.next() instanceof TraceRecord.Header h && h.fields().get("created") instanceof String created) {
                Instant i = OffsetDateTime.parse(created).toInstant();
                return Math.addExact(Math.multiplyExact(i.getEpochSecond(), 1_000_000_000L), i.getNano());
            }
        } catch (TraceFormatException | DateTimeParseException | ArithmeticException e) {
            // no usable date: the problem with the header itself is reported by the import
        }
        return 0;
    }

    private static long nanos(double t) {
        return Math.round(t * 1e9);
    }
}
