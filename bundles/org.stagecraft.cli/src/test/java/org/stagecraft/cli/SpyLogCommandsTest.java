package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.spy.log.SpyLogWriter;

/** decode and stats read spy logs (MCAP) and print what they print for the trace the log was made from. */
class SpyLogCommandsTest {
    @TempDir
    Path tmp;

    private record Result(int code, String out, String err) {
    }

    private static Result run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = Main.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        return new Result(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    private static Path trace(String name) {
        return TraceCorpus.file(name);
    }

    /** The spy's way: every framed event of the trace, stamped with its receive time. */
    private Path logOf(Path trace) throws IOException {
        Path log = tmp.resolve(trace.getFileName() + ".mcap");
        try (SpyLogWriter w = SpyLogWriter.create(log, Map.of("trace", trace.getFileName().toString()))) {
            TraceFraming.frame(trace, e -> {
                try {
                    w.wire(Math.round(e.t() * 1e9), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event());
                } catch (IOException ex) {
                    throw new UncheckedIOException(ex);
                }
            });
        }
        return log;
    }

    @Test
    void decodeAndStatsOfASpyLogPrintWhatTheyPrintForItsTrace() throws IOException {
        for (String name : List.of("requests.reqclient.trace.jsonl", "pioneer-laser-sonar.gt.trace.jsonl")) {
            Path trace = trace(name);
            Path log = logOf(trace);
            Result fromTrace = run("decode", trace.toString());
            Result fromLog = run("decode", log.toString());
            assertEquals(0, fromLog.code(), fromLog.err());
            assertTrue(fromLog.out().lines().count() > 1000, name);
            assertEquals(fromTrace.out(), fromLog.out(), name);
            Result statsTrace = run("stats", trace.toString());
            Result statsLog = run("stats", log.toString());
            assertEquals(0, statsLog.code(), statsLog.err());
            assertEquals(statsTrace.out(), statsLog.out(), name);
        }
    }

    @Test
    void aCutOffLogDecodesItsCompleteChunksAndABrokenOneIsReported() throws IOException {
        Path log = tmp.resolve("small.mcap");
        Path trace = trace("requests.reqclient.trace.jsonl");
        try (SpyLogWriter w = SpyLogWriter.create(
                java.nio.channels.FileChannel.open(log, java.nio.file.StandardOpenOption.CREATE,
                        java.nio.file.StandardOpenOption.WRITE), Map.of(), 16 * 1024)) {
            TraceFraming.frame(trace, e -> {
                try {
                    w.wire(Math.round(e.t() * 1e9), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event());
                } catch (IOException ex) {
                    throw new UncheckedIOException(ex);
                }
            });
        }
        byte[] bytes = Files.readAllBytes(log);
        Path cut = tmp.resolve("cut.mcap");
        Files.write(cut, Arrays.copyOf(bytes, bytes.length / 2));
        List<String> full = run("decode", trace.toString()).out().lines().toList();
        Result r = run("decode", cut.toString());
        assertEquals(0, r.code(), r.err());
        List<String> part = r.out().lines().toList();
        assertTrue(part.size() > 100 && part.size() < full.size(), part.size() + " of " + full.size());
        assertEquals(full.subList(0, part.size()), part);

        Path broken = tmp.resolve("broken.mcap");
        byte[] b = bytes.clone();
        for (int i = 200; i < 400; i++) {
            b[i] = 0; // inside the first chunk
        }
        Files.write(broken, b);
        Result bad = run("decode", broken.toString());
        assertEquals(1, bad.code());
        assertTrue(bad.err().contains("broken.mcap") && bad.err().contains("chunk"), bad.err());
    }
}
