package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.spy.log.SpyLogWriter;

/** decode and stats read spy logs (MCAP) and print what they print for the trace the log was made from. */
class SpyLogCommandsTest {
    @TempDir
    Path tmp;

    private static CommandRun run(String... args) {
        return CommandRun.of(args);
    }

    private static Path trace(String name) {
        return TraceCorpus.file(name);
    }

    /** The spy's way: every framed event of the trace, stamped with its receive time. */
    private Path logOf(Path trace) throws IOException {
        return DamagedLogs.logOf(trace, tmp.resolve(trace.getFileName() + ".mcap"), SpyLogWriter.DEFAULT_CHUNK_SIZE);
    }

    @Test
    void decodeAndStatsOfASpyLogPrintWhatTheyPrintForItsTrace() throws IOException {
        for (String name : List.of("requests.reqclient.trace.jsonl", "pioneer-laser-sonar.gt.trace.jsonl")) {
            Path trace = trace(name);
            Path log = logOf(trace);
            CommandRun fromTrace = run("decode", trace.toString());
            CommandRun fromLog = run("decode", log.toString());
            assertEquals(0, fromLog.code(), fromLog.err());
            assertTrue(fromLog.out().lines().count() > 1000, name);
            assertEquals(fromTrace.out(), fromLog.out(), name);
            CommandRun statsTrace = run("stats", trace.toString());
            CommandRun statsLog = run("stats", log.toString());
            assertEquals(0, statsLog.code(), statsLog.err());
            assertEquals(statsTrace.out(), statsLog.out(), name);
        }
    }

    @Test
    void aCutOffLogDecodesItsCompleteChunksAndABrokenOneIsReported() throws IOException {
        Path trace = trace("requests.reqclient.trace.jsonl");
        Path log = DamagedLogs.logOf(trace, tmp.resolve("small.mcap"), 16 * 1024);
        byte[] bytes = Files.readAllBytes(log);
        Path cut = tmp.resolve("cut.mcap");
        Files.write(cut, Arrays.copyOf(bytes, bytes.length / 2));
        List<String> full = run("decode", trace.toString()).out().lines().toList();
        CommandRun r = run("decode", cut.toString());
        assertEquals(ExitCode.LOSSES, r.code(), "the cut-off end is lost: " + r.err());
        List<String> part = r.out().lines().toList();
        assertTrue(part.size() > 100 && part.size() < full.size(), part.size() + " of " + full.size());
        assertEquals(full.subList(0, part.size()), part);

        Path broken = tmp.resolve("broken.mcap");
        Files.write(broken, DamagedLogs.damageChunk(bytes, 0));
        CommandRun bad = run("decode", broken.toString());
        assertEquals(ExitCode.LOSSES, bad.code(), "the other chunks are read, chunk 0 is lost: " + bad.err());
        assertTrue(bad.err().contains("broken.mcap") && bad.err().contains("skipped") && bad.err().contains("chunk 0"),
                bad.err());
        List<String> rest = bad.out().lines().toList();
        assertTrue(rest.size() > 100 && rest.size() < full.size(), rest.size() + " of " + full.size());
        assertEquals(full.subList(full.size() - rest.size(), full.size()), rest, "everything after the first chunk");
    }

    // --- damaged logs (issue 17, item 6) ---------------------------------------------------------

    /** A log of the trace in chunks of 4 KiB (dozens of them). */
    private Path smallChunkLog(Path trace, String name) throws IOException {
        return DamagedLogs.logOf(trace, tmp.resolve(name), 4 * 1024);
    }

    /** Lines of decode: one per banner, message and unframed piece, as the log's messages. */
    private static long decoded(Path file) {
        CommandRun r = run("decode", file.toString());
        return r.out().lines().count();
    }

    @Test
    void aDamagedChunkTenOfManyWithTheFooterIntactIsSkippedAndStatsSaysWhatWasLost() throws IOException {
        Path trace = trace("pioneer-laser-sonar.gt.trace.jsonl");
        byte[] file = Files.readAllBytes(smallChunkLog(trace, "ten.mcap"));
        assertTrue(DamagedLogs.chunkOffsets(file).size() > 16, DamagedLogs.chunkOffsets(file).size() + " chunks");
        Path damaged = Files.write(tmp.resolve("ten-damaged.mcap"), DamagedLogs.damageChunk(file, 10));
        CommandRun r = run("stats", damaged.toString());
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
        assertTrue(r.err().contains("skipped") && r.err().contains("chunk 10"), r.err());
        assertTrue(!r.err().contains("not closed properly"), "the summary is intact: " + r.err());
        long lost = DamagedLogs.messagesLost(r.err());
        assertTrue(lost > 0, r.err());
        assertEquals(decoded(trace) - lost, decoded(damaged), "only chunk 10's messages are missing");
    }

    @Test
    void withoutTheFooterEveryIntactChunkAfterADamagedChunkTenIsRecovered() throws IOException {
        Path trace = trace("pioneer-laser-sonar.gt.trace.jsonl");
        byte[] file = Files.readAllBytes(smallChunkLog(trace, "ten.mcap"));
        Path damaged = Files.write(tmp.resolve("ten-no-footer.mcap"), DamagedLogs.withoutFooter(DamagedLogs.damageChunk(file, 10)));
        CommandRun r = run("stats", damaged.toString());
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
        assertTrue(r.err().contains("not closed properly") && r.err().contains("skipped")
                && r.err().contains("chunk 10"), r.err());
        long lost = DamagedLogs.messagesLost(r.err());
        assertTrue(lost > 0, r.err());
        assertEquals(decoded(trace) - lost, decoded(damaged), "only chunk 10's messages are missing");
    }

    @Test
    void withoutTheFooterAChunkWhoseLengthIsDamagedIsSkippedByFindingTheNextChunk() throws IOException {
        Path trace = trace("pioneer-laser-sonar.gt.trace.jsonl");
        byte[] file = Files.readAllBytes(smallChunkLog(trace, "ten.mcap"));
        List<Long> chunks = DamagedLogs.chunkOffsets(file);
        byte[] b = DamagedLogs.withoutFooter(file);
        b[(int) (chunks.get(10) + 1)] ^= 0x40; // the chunk's length: the records after it no longer line up
        Path damaged = Files.write(tmp.resolve("ten-length.mcap"), b);
        List<String> full = run("decode", trace.toString()).out().lines().toList();
        CommandRun r = run("decode", damaged.toString());
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
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
        Path damaged = Files.write(tmp.resolve("first-no-footer.mcap"), DamagedLogs.withoutFooter(DamagedLogs.damageChunk(file, 0)));
        CommandRun r = run("stats", damaged.toString());
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
        assertTrue(r.err().contains("skipped") && r.err().contains("chunk 0"), r.err());
        long lost = DamagedLogs.messagesLost(r.err());
        assertTrue(lost > 0, r.err());
        assertEquals(decoded(trace) - lost, decoded(damaged), "the chunks after the first are read");
    }

    @Test
    void aLogWhoseOnlyChunkIsDamagedFailsSayingNothingCouldBeRead() throws IOException {
        Path log = DamagedLogs.logOf(trace("requests.reqclient.trace.jsonl"), tmp.resolve("one.mcap"),
                SpyLogWriter.DEFAULT_CHUNK_SIZE);
        byte[] file = Files.readAllBytes(log);
        assertEquals(1, DamagedLogs.chunkOffsets(file).size());
        for (byte[] b : List.of(DamagedLogs.damageChunk(file, 0), DamagedLogs.withoutFooter(DamagedLogs.damageChunk(file, 0)))) {
            Path damaged = Files.write(tmp.resolve("one-damaged.mcap"), b);
            CommandRun r = run("stats", damaged.toString());
            assertEquals(ExitCode.FAILED, r.code(), r.err());
            assertTrue(r.err().contains("nothing could be read") && r.err().contains("chunk 0"), r.err());
        }
    }
}
