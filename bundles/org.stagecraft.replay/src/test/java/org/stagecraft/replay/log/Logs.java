package org.stagecraft.replay.log;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceFraming;

/** Test helpers: what a trace holds, framed independently of the code under test. */
public final class Logs {
    private Logs() {
    }

    public static final String GT = "pioneer-laser-sonar.gt.trace.jsonl";

    public static Path trace(String name) {
        return TraceCorpus.file(name);
    }

    /** Every banner, message and unframed piece of the trace, in the order the framer completes them. */
    public static List<SessionEvent> framed(Path trace) {
        List<SessionEvent> out = new ArrayList<>();
        try {
            TraceFraming.frame(trace, out::add);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out;
    }

    /** Every message a fresh cursor gives from the start of the log to its end. */
    public static List<LogMessage> all(SessionLog log) throws IOException {
        List<LogMessage> out = new ArrayList<>();
        try (LogCursor c = log.cursor(Long.MIN_VALUE)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                out.add(m);
            }
        }
        return out;
    }

    /** The trace written into {@code out} as a spy log (chunks of {@code chunkSize} bytes), as the spy would. */
    public static Path spyLog(Path trace, Path out, int chunkSize) throws IOException {
        try (var ch = java.nio.file.Files.newByteChannel(out, java.nio.file.StandardOpenOption.CREATE_NEW,
                java.nio.file.StandardOpenOption.WRITE);
                org.stagecraft.spy.log.SpyLogWriter w = org.stagecraft.spy.log.SpyLogWriter.create(ch, java.util.Map.of(), chunkSize)) {
            List<LogProblem> problems = TraceImport.convert(trace, w);
            if (!problems.isEmpty()) {
                throw new IOException("the trace did not go in whole: " + problems);
            }
        }
        return out;
    }

    public static long nanos(double t) {
        return Math.round(t * 1e9);
    }
}
