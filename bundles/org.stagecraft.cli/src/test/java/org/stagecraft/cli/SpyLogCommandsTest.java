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
        Files.write(broken, damageChunk(bytes, 0));
        Result bad = run("decode", broken.toString());
        assertEquals(0, bad.code(), "the other chunks are read: " + bad.err());
        assertTrue(bad.err().contains("broken.mcap") && bad.err().contains("skipped") && bad.err().contains("chunk 0"),
                bad.err());
        List<String> rest = bad.out().lines().toList();
        assertTrue(rest.size() > 100 && rest.size() < full.size(), rest.size() + " of " + full.size());
        assertEquals(full.subList(full.size() - rest.size(), full.size()), rest, "everything after the first chunk");
    }

    // --- damaged logs (issue 17, item 6) ---------------------------------------------------------

    /** A log of the trace in chunks of 4 KiB (dozens of them). */
    private Path smallChunkLog(Path trace, String name) throws IOException {
        Path log = tmp.resolve(name);
        try (SpyLogWriter w = SpyLogWriter.create(
                java.nio.channels.FileChannel.open(log, java.nio.file.StandardOpenOption.CREATE,
                        java.nio.file.StandardOpenOption.WRITE), Map.of(), 4 * 1024)) {
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

    /** File offsets of the chunk records, walking the records from the start (MCAP: opcode u8, length u64 LE). */
    private static List<Long> chunkOffsets(byte[] file) {
        List<Long> out = new java.util.ArrayList<>();
        int p = 8;
        while (p + 9 <= file.length) {
            int op = file[p] & 0xff;
            long len = java.nio.ByteBuffer.wrap(file, p + 1, 8).order(java.nio.ByteOrder.LITTLE_ENDIAN).getLong();
            if (op == 0x06) {
                out.add((long) p);
            }
            if (op == 0x0F) {
                break; // data end: the summary follows
            }
            p += 9 + (int) len;
        }
        return out;
    }

    /** Zeroes 64 bytes in the middle of chunk {@code n}'s compressed records (its CRC fails). */
    private static byte[] damageChunk(byte[] file, int n) {
        byte[] b = file.clone();
        List<Long> chunks = chunkOffsets(file);
        long at = chunks.get(n);
        long end = n + 1 < chunks.size() ? chunks.get(n + 1) : at + 200;
        Arrays.fill(b, (int) (at + (end - at) / 2), (int) (at + (end - at) / 2) + 64, (byte) 0);
        return b;
    }

    /** The file without its footer and closing magic, as a crash after the last chunk leaves it. */
    private static byte[] withoutFooter(byte[] file) {
        return Arrays.copyOf(file, file.length - (9 + 20 + 8));
    }

    private static long messagesLost(String err) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("; (\\d+) messages? lost").matcher(err);
        long n = 0;
        while (m.find()) {
            n += Long.parseLong(m.group(1));
        }
        return n;
    }

    /** Lines of decode: one per banner, message and unframed piece, as the log's messages. */
    private static long decoded(Path file) {
        Result r = run("decode", file.toString());
        return r.out().lines().count();
    }

    @Test
    void aDamagedChunkTenOfManyWithTheFooterIntactIsSkippedAndStatsSaysWhatWasLost() throws IOException {
        Path trace = trace("pioneer-laser-sonar.gt.trace.jsonl");
        byte[] file = Files.readAllBytes(smallChunkLog(trace, "ten.mcap"));
        assertTrue(chunkOffsets(file).size() > 16, chunkOffsets(file).size() + " chunks");
        Path damaged = Files.write(tmp.resolve("ten-damaged.mcap"), damageChunk(file, 10));
        Result r = run("stats", damaged.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("skipped") && r.err().contains("chunk 10"), r.err());
        assertTrue(!r.err().contains("not closed properly"), "the summary is intact: " + r.err());
        long lost = messagesLost(r.err());
        assertTrue(lost > 0, r.err());
        assertEquals(decoded(trace) - lost, decoded(damaged), "only chunk 10's messages are missing");
    }

    @Test
    void withoutTheFooterEveryIntactChunkAfterADamagedChunkTenIsRecovered() throws IOException {
        Path trace = trace("pioneer-laser-sonar.gt.trace.jsonl");
        byte[] file = Files.readAllBytes(smallChunkLog(trace, "ten.mcap"));
        Path damaged = Files.write(tmp.resolve("ten-no-footer.mcap"), withoutFooter(damageChunk(file, 10)));
        Result r = run("stats", damaged.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("not closed properly") && r.err().contains("skipped")
                && r.err().contains("chunk 10"), r.err());
        long lost = messagesLost(r.err());
        assertTrue(lost > 0, r.err());
        assertEquals(decoded(trace) - lost, decoded(damaged), "only chunk 10's messages are missing");
    }

    @Test
    void withoutTheFooterAChunkWhoseLengthIsDamagedIsSkippedByFindingTheNextChunk() throws IOException {
        Path trace = trace("pioneer-laser-sonar.gt.trace.jsonl");
        byte[] file = Files.readAllBytes(smallChunkLog(trace, "ten.mcap"));
        List<Long> chunks = chunkOffsets(file);
        byte[] b = withoutFooter(file);
        b[(int) (chunks.get(10) + 1)] ^= 0x40; // the chunk's length: the records after it no longer line up
        Path damaged = Files.write(tmp.resolve("ten-length.mcap"), b);
        List<String> full = run("decode", trace.toString()).out().lines().toList();
        Result r = run("decode", damaged.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("skipped") && r.err().contains("bytes " + chunks.get(10) + ".."), r.err());
        List<String> part = r.out().lines().toList();
        assertTrue(part.size() < full.size(), part.size() + " of " + full.size());
        assertEquals(full.get(full.size() - 1), part.get(part.size() - 1), "the chunks after chunk 10 are read");
        assertTrue(full.size() - part.size() < full.size() / chunks.size() * 3,
                "about one chunk is lost: " + (full.size() - part.size()) + " of " + full.size() + " lines");
    }

    @Test
    void withoutTheFooterADamagedFirstChunkLosesOnlyItsOwnMessages() throws IOException {
        Path trace = trace("pioneer-laser-sonar.gt.trace.jsonl");
        byte[] file = Files.readAllBytes(smallChunkLog(trace, "first.mcap"));
        Path damaged = Files.write(tmp.resolve("first-no-footer.mcap"), withoutFooter(damageChunk(file, 0)));
        Result r = run("stats", damaged.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("skipped") && r.err().contains("chunk 0"), r.err());
        long lost = messagesLost(r.err());
        assertTrue(lost > 0, r.err());
        assertEquals(decoded(trace) - lost, decoded(damaged), "the chunks after the first are read");
    }

    @Test
    void aLogWhoseOnlyChunkIsDamagedFailsSayingNothingCouldBeRead() throws IOException {
        Path log = tmp.resolve("one.mcap");
        try (SpyLogWriter w = SpyLogWriter.create(log, Map.of())) {
            TraceFraming.frame(trace("requests.reqclient.trace.jsonl"), e -> {
                try {
                    w.wire(Math.round(e.t() * 1e9), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event());
                } catch (IOException ex) {
                    throw new UncheckedIOException(ex);
                }
            });
        }
        byte[] file = Files.readAllBytes(log);
        assertEquals(1, chunkOffsets(file).size());
        for (byte[] b : List.of(damageChunk(file, 0), withoutFooter(damageChunk(file, 0)))) {
            Path damaged = Files.write(tmp.resolve("one-damaged.mcap"), b);
            Result r = run("stats", damaged.toString());
            assertEquals(1, r.code(), r.err());
            assertTrue(r.err().contains("nothing could be read") && r.err().contains("chunk 0"), r.err());
        }
    }
}
