package org.stagecraft.replay.log;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.stagecraft.recording.trace.TraceFormatException;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * Writes a recorded trace ({@code *.trace.jsonl}) into a spy log the way the spy would have logged
 * the same traffic: the chunks framed per connection and direction, every banner, message and piece
 * of unframed bytes at the time of the chunk that completed it, connections opened and closed. A
 * trace that stops being readable (a bad line, a cut-off file) is imported up to that line, and the
 * problem says which line.
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
        long[] last = { 0 };
        try (TraceReader reader = new TraceReader(trace)) {
            try {
                TraceFraming.frame(reader, e -> {
                    last[0] = nanos(e.t());
                    write(() -> out.wire(nanos(e.t()), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event()));
                }, l -> {
                    last[0] = nanos(l.t());
                    write(() -> {
                        if (l.isClose()) {
                            out.connectionClosed(nanos(l.t()), l.conn(), "closed (recorded)");
                        } else {
                            out.connectionOpened(nanos(l.t()), l.conn(), clientAddress(l.conn()), playerAddress(l.port()),
                                    playerAddress(l.port()));
                        }
                    });
                });
            } catch (TraceFormatException e) {
                problems.add(new LogProblem("line " + reader.line(), last[0],
                        e.getMessage() + "; the trace is read up to the line before"));
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

    private static long nanos(double t) {
        return Math.round(t * 1e9);
    }
}
