package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.stagecraft.recording.trace.TraceCorpus;

/**
 * Issue 25, items 1-3: one rule for every command's exit code ({@link ExitCode}), data lost said with
 * counts, and a message that names the file once, the line or bytes, and what the file is not.
 */
class ExitCodesTest {
    private static final String GT = "pioneer-laser-sonar.gt.trace.jsonl";

    @TempDir
    Path tmp;

    /** A spy log of the recorded session in chunks of 16 KiB, damaged by {@code damage}. */
    private Path damagedLog(String name, java.util.function.UnaryOperator<byte[]> damage) throws IOException {
        byte[] whole = Files.readAllBytes(DamagedLogs.logOf(TraceCorpus.file(GT), tmp.resolve("whole.mcap"), 16 * 1024));
        assertTrue(DamagedLogs.chunkOffsets(whole).size() > 8, "enough chunks to damage one in the middle");
        return Files.write(tmp.resolve(name), damage.apply(whole));
    }

    private String[] exportArgs(Path in, String format) {
        return new String[] { "export", in.toString(), "--format", format, "--out", tmp.resolve("out." + format).toString() };
    }

    /** Rows the CSV export of the undamaged recording has (counted, not written down). */
    private long rowsOfTheWholeRecording() {
        CommandRun r = CommandRun.of("export", TraceCorpus.file(GT).toString(), "--format", "csv");
        assertEquals(ExitCode.DONE, r.code(), r.err());
        return r.out().lines().count() - 1;
    }

    // --- item 1: export says what it lost ---------------------------------------------------------

    @ParameterizedTest
    @ValueSource(strings = { "csv", "mcap", "writelog" })
    void exportOfALogWithADamagedChunkSaysWhatWasLostAndExitsWithLosses(String format) throws IOException {
        Path log = damagedLog("crc.mcap", b -> DamagedLogs.damageChunk(b, 4));
        CommandRun r = CommandRun.of(exportArgs(log, format));
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
        assertTrue(r.err().contains("chunk 4") && r.err().contains("CRC"), "names the damaged chunk: " + r.err());
        long lost = DamagedLogs.messagesLost(r.err());
        assertTrue(lost > 0, "counts the messages lost: " + r.err());
        assertTrue(r.err().contains("done with losses"), r.err());
        assertTrue(Files.size(tmp.resolve("out." + format)) > 0, "what could be read is exported");
        // decode and stats count the same loss
        CommandRun stats = CommandRun.of("stats", log.toString());
        assertEquals(ExitCode.LOSSES, stats.code(), stats.err());
        assertEquals(lost, DamagedLogs.messagesLost(stats.err()), stats.err());
    }

    @Test
    void theCsvExportOfADamagedLogLacksExactlyTheMessagesItSaysAreLost() throws IOException {
        Path log = damagedLog("crc.mcap", b -> DamagedLogs.damageChunk(b, 4));
        CommandRun r = CommandRun.of("export", log.toString(), "--format", "csv");
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
        long rows = r.out().lines().count() - 1;
        // the chunk's banners count among its messages; CSV has a row per Player message only, and the
        // recording's one banner is in chunk 0
        assertEquals(rowsOfTheWholeRecording() - DamagedLogs.messagesLost(r.err()), rows, r.err());
    }

    @ParameterizedTest
    @ValueSource(strings = { "csv", "mcap", "writelog" })
    void exportOfALogWithADamagedChunkLengthSaysWhereAndExitsWithLosses(String format) throws IOException {
        Path log = damagedLog("length.mcap", b -> DamagedLogs.withoutFooter(DamagedLogs.damageChunkLength(b, 4)));
        long chunk4 = DamagedLogs.chunkOffsets(Files.readAllBytes(tmp.resolve("whole.mcap"))).get(4);
        CommandRun r = CommandRun.of(exportArgs(log, format));
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
        assertTrue(r.err().contains("bytes " + chunk4 + ".."), "says where the damage starts: " + r.err());
        assertTrue(r.err().contains("not closed properly") || r.err().contains("no summary"), r.err());
    }

    @Test
    void aLogCutOffInsideAChunkLosesItsEndAndSaysSo() throws IOException {
        Path log = damagedLog("cut.mcap", b -> Arrays.copyOf(b, b.length / 2));
        for (String command : List.of("decode", "stats")) {
            CommandRun r = CommandRun.of(command, log.toString());
            assertEquals(ExitCode.LOSSES, r.code(), command + ": " + r.err());
            assertTrue(r.err().contains("cut off"), r.err());
        }
        CommandRun export = CommandRun.of(exportArgs(log, "csv"));
        assertEquals(ExitCode.LOSSES, export.code(), export.err());
        assertTrue(export.err().contains("the incomplete record after them is lost"), export.err());
    }

    @Test
    void aLogThatEndsAfterAWholeChunkButWasNeverClosedIsReadWholeWithANote() throws IOException {
        byte[] whole = Files.readAllBytes(DamagedLogs.logOf(TraceCorpus.file(GT), tmp.resolve("whole.mcap"), 16 * 1024));
        List<Long> chunks = DamagedLogs.chunkOffsets(whole);
        // a spy killed between two chunk writes leaves the file ending exactly before a chunk
        Path log = Files.write(tmp.resolve("killed.mcap"), Arrays.copyOf(whole, chunks.get(chunks.size() - 1).intValue()));
        for (String command : List.of("decode", "stats")) {
            CommandRun r = CommandRun.of(command, log.toString());
            assertEquals(ExitCode.DONE, r.code(), command + ": all of the file was read: " + r.err());
            assertTrue(r.err().contains("not closed properly"), "but it is said: " + r.err());
        }
        CommandRun export = CommandRun.of(exportArgs(log, "csv"));
        assertEquals(ExitCode.DONE, export.code(), export.err());
        assertTrue(export.err().contains("no summary"), export.err());
    }

    // --- item 2: export of a file it cannot read at all -----------------------------------------

    private Path trace(String name, String firstLine) throws IOException {
        return Files.writeString(tmp.resolve(name), firstLine + "\n", StandardCharsets.UTF_8);
    }

    /** Exit 1, no output file, each line naming the file once, and the line when a line is at fault. */
    private void assertNothingReadable(CommandRun r, Path file, String line, String reason) {
        assertEquals(ExitCode.FAILED, r.code(), r.err());
        assertTrue(r.err().contains(reason), "the reason '" + reason + "' in: " + r.err());
        assertTrue(r.err().contains(line), "the place '" + line + "' in: " + r.err());
        assertFalse(r.err().contains("line 0") || r.err().contains(":0:"), "no line 0: " + r.err());
        for (String l : r.err().lines().toList()) {
            assertTrue(count(l, file.toString()) <= 1, "the file is named once: " + l);
        }
        assertFalse(r.err().contains("Exception") || r.err().contains("\tat "), r.err());
        assertFalse(Files.exists(tmp.resolve("out.csv")), "no empty output file");
    }

    private static int count(String text, String part) {
        Matcher m = Pattern.compile(Pattern.quote(part)).matcher(text);
        int n = 0;
        while (m.find()) {
            n++;
        }
        return n;
    }

    @ParameterizedTest
    @ValueSource(strings = { "\"x\"", "2" })
    void exportOfATraceWithAnUnsupportedVersionFailsNamingTheFileOnceAndTheLine(String version) throws IOException {
        Path f = trace("b.trace.jsonl", "{\"format\":\"player-trace\",\"version\":" + version + "}");
        CommandRun r = CommandRun.of(exportArgs(f, "csv"));
        assertNothingReadable(r, f, "line 1", "unsupported player-trace version " + version);
        CommandRun decode = CommandRun.of("decode", f.toString());
        assertEquals(ExitCode.FAILED, decode.code(), decode.err());
    }

    @Test
    void exportOfATraceWhoseFirstLineIsTooLongFailsAtLineOne() throws IOException {
        Path f = tmp.resolve("long.trace.jsonl");
        try (OutputStream out = Files.newOutputStream(f)) {
            out.write("{\"format\":\"player-trace\",\"version\":1,\"note\":\"".getBytes(StandardCharsets.US_ASCII));
            byte[] block = new byte[1 << 20];
            Arrays.fill(block, (byte) 'A');
            for (int i = 0; i < 17; i++) {
                out.write(block);
            }
            out.write("\"}\n".getBytes(StandardCharsets.US_ASCII));
        }
        CommandRun r = CommandRun.of(exportArgs(f, "csv"));
        assertNothingReadable(r, f, "line 1", "line too long");
    }

    @Test
    void aTraceWithABadLineInTheMiddleIsDecodedUpToItAndTheRestIsSaidLost() throws IOException {
        List<String> lines = Files.readAllLines(TraceCorpus.file(GT), StandardCharsets.UTF_8);
        int bad = lines.size() / 2;
        List<String> damaged = new java.util.ArrayList<>(lines);
        damaged.set(bad, "{not json");
        Path f = Files.write(tmp.resolve("middle.trace.jsonl"), damaged, StandardCharsets.UTF_8);
        CommandRun r = CommandRun.of("decode", f.toString());
        assertEquals(ExitCode.LOSSES, r.code(), r.err());
        assertTrue(r.err().startsWith("stagecraft decode: " + f + ":" + (bad + 1) + ": not valid JSON"), r.err());
        assertTrue(r.err().contains("nothing after that line was read"), r.err());
        assertTrue(r.out().lines().count() > 100, "what came before the line is decoded");
        CommandRun export = CommandRun.of(exportArgs(f, "csv"));
        assertEquals(ExitCode.LOSSES, export.code(), export.err());
        assertTrue(export.err().contains(f + ": line " + (bad + 1) + ": not valid JSON"), export.err());
    }

    // --- item 3: the same code for the same problem, and what a file is not ----------------------

    @Test
    void aFolderIsTheSameFailureForEveryCommand() throws IOException {
        assertTheSameFailureForEveryCommand(Files.createDirectory(tmp.resolve("a-folder.mcap")), "a folder, not a file");
    }

    @Test
    void aMissingFileIsTheSameFailureForEveryCommand() {
        assertTheSameFailureForEveryCommand(tmp.resolve("gone.mcap"), "no such file");
    }

    private void assertTheSameFailureForEveryCommand(Path input, String why) {
        for (String[] args : List.of(new String[] { "decode", input.toString() }, new String[] { "stats", input.toString() },
                exportArgs(input, "csv"), new String[] { "replay", input.toString(), "--to", "127.0.0.1:0" })) {
            CommandRun r = CommandRun.of(args);
            assertEquals(ExitCode.FAILED, r.code(), args[0] + ": " + r.err());
            assertEquals("stagecraft " + args[0] + ": " + input + ": " + why + System.lineSeparator(), r.err());
        }
    }

    @Test
    void usageErrorsAreTwoForEveryCommand() {
        for (String[] args : List.of(new String[] { "decode" }, new String[] { "stats", "a", "b" },
                new String[] { "export", "x.mcap" }, new String[] { "replay", "x.mcap" }, new String[] { "frobnicate" })) {
            assertEquals(ExitCode.USAGE, CommandRun.of(args).code(), String.join(" ", args));
        }
    }

    @ParameterizedTest
    @ValueSource(ints = { 0, 5, 3000 })
    void aFileNamedMcapThatIsNotIsSaidToBeNoMcapFile(int size) throws IOException {
        byte[] bytes = new byte[size];
        new Random(size).nextBytes(bytes);
        if (size > 0) {
            bytes[0] = '{'; // text-like: formerly read as a player-trace and refused as one
        }
        Path f = Files.write(tmp.resolve("r" + size + ".mcap"), bytes);
        for (String[] args : List.of(new String[] { "decode", f.toString() }, new String[] { "stats", f.toString() },
                exportArgs(f, "csv"))) {
            CommandRun r = CommandRun.of(args);
            assertEquals(ExitCode.FAILED, r.code(), r.err());
            assertTrue(r.err().startsWith("stagecraft " + args[0] + ": " + f + ": not an MCAP file: "), r.err());
            assertTrue(r.err().contains(size == 0 ? "it is empty" : size < 8 ? "only 5 bytes" : "does not start with MCAP's magic"),
                    r.err());
            assertFalse(r.err().contains("player-trace") || r.err().contains("UTF-8"), r.err());
            assertEquals(1, r.err().lines().count(), r.err());
        }
    }
}
