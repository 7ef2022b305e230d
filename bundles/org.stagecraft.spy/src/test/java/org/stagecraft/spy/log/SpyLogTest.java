package org.stagecraft.spy.log;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.mcap.Mcap;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.FillingChannel;
import org.stagecraft.spy.FillingFile;

class SpyLogTest {
    /** Footer record (opcode, length, 20 bytes) and the closing magic. */
    private static final int MCAP_TAIL = 9 + 20 + 8;

    @TempDir
    Path tmp;

    private static List<LogEntry> all(Iterator<LogEntry> it) {
        List<LogEntry> out = new ArrayList<>();
        it.forEachRemaining(out::add);
        return out;
    }

    private static List<LogEntry.Wire> wires(List<LogEntry> entries) {
        return entries.stream().filter(e -> e instanceof LogEntry.Wire).map(e -> (LogEntry.Wire) e).toList();
    }

    private static void assertTimeOrder(List<LogEntry> entries) {
        for (int i = 1; i < entries.size(); i++) {
            assertTrue(entries.get(i - 1).timeNanos() <= entries.get(i).timeNanos(), "time order at entry " + i);
        }
    }

    private static void assertSameEntry(LogEntry a, LogEntry b) {
        if (a instanceof LogEntry.Wire x && b instanceof LogEntry.Wire y) {
            assertEquals(x.timeNanos(), y.timeNanos());
            assertEquals(x.conn(), y.conn());
            assertEquals(x.dir(), y.dir());
            assertEquals(x.streamOffset(), y.streamOffset());
            assertEquals(x.kind(), y.kind());
            assertArrayEquals(x.bytes(), y.bytes());
        } else {
            assertEquals(a, b);
        }
    }

    // --- every shared trace ----------------------------------------------------------------------

    @Test
    void everySharedTraceRoundTripsExactly() throws IOException {
        for (Path trace : TraceLogs.all()) {
            String name = trace.getFileName().toString();
            Path log = tmp.resolve(name + ".mcap");
            Map<String, String> meta = Map.of("trace", name, "listen", "6665", "upstream", "16665");
            TraceLogs.Expected x = TraceLogs.writeFile(trace, log, meta);
            try (SpyLogReader r = SpyLogReader.open(log)) {
                assertFalse(r.recovered(), name);
                assertEquals(meta, r.metadata(), name);
                assertEquals(x.banners + x.frames + x.unframed, r.messageCount(), name);
                assertEquals(x.opened.size() + x.closed.size(), r.eventCount(), name);
                assertEquals(0, r.chunksRead(), name + ": opening reads the summary, not the chunks");
                for (TraceLogs.StreamKey k : x.streams.keySet()) {
                    assertArrayEquals(x.stream(k.conn(), k.dir()), r.streamBytes(k.conn(), k.dir()),
                            name + " " + k);
                }
                List<LogEntry> entries = all(r.entries());
                assertEquals(r.messageCount() + r.eventCount(), entries.size(), name);
                assertTimeOrder(entries);
                assertEquals(entries.get(0).timeNanos(), r.startTimeNanos(), name);
                assertEquals(entries.get(entries.size() - 1).timeNanos(), r.endTimeNanos(), name);
                List<LogEntry.Wire> wires = wires(entries);
                assertEquals(x.wire.size(), wires.size(), name);
                for (int i = 0; i < wires.size(); i++) {
                    SessionEvent e = x.wire.get(i);
                    LogEntry.Wire w = wires.get(i);
                    assertEquals(TraceLogs.nanos(e.t()), w.timeNanos(), name + " entry " + i);
                    assertEquals(e.stream().conn(), w.conn());
                    assertEquals(e.stream().port(), w.port());
                    assertEquals(e.stream().dir(), w.dir());
                    assertEquals(e.event().offset(), w.streamOffset());
                    assertArrayEquals(e.event().bytes(), w.bytes(), name + " entry " + i);
                    LogEntry.Kind kind = switch (e.event()) {
                        case WireEvent.Banner b -> LogEntry.Kind.BANNER;
                        case WireEvent.Frame f -> LogEntry.Kind.FRAME;
                        case WireEvent.Unframed u -> LogEntry.Kind.UNFRAMED;
                    };
                    assertEquals(kind, w.kind());
                }
                List<LogConnection> conns = r.connections();
                assertEquals(x.opened.keySet().stream().toList(), conns.stream().map(LogConnection::conn).toList(), name);
                for (LogConnection c : conns) {
                    assertEquals(x.opened.get(c.conn()), c.openedNanos());
                    assertEquals(x.closed.getOrDefault(c.conn(), -1L), c.closedNanos());
                    assertEquals("trace client", c.client());
                    if (x.ports.containsKey(c.conn())) {
                        assertEquals(x.ports.get(c.conn()), c.port());
                    }
                }
                List<LogConnection> indexed = r.indexedConnections();
                assertEquals(x.ports.keySet().stream().sorted().toList(), indexed.stream().map(LogConnection::conn).toList(),
                        name + ": every connection with bytes is known from the summary");
                for (LogConnection c : indexed) {
                    LogConnection full = conns.stream().filter(k -> k.conn() == c.conn()).findFirst().orElseThrow();
                    assertEquals(List.of(full.port(), full.client(), full.listen(), full.upstream()),
                            List.of(c.port(), c.client(), c.listen(), c.upstream()), name + " connection " + c.conn());
                }
                assertTrue(Files.size(log) * 2 < x.rawBytes,
                        name + ": compressed " + Files.size(log) + " bytes for " + x.rawBytes + " raw");
            }
        }
    }

    @Test
    void chunksAreZstdCompressedAndIndexed() throws IOException {
        Path log = tmp.resolve("gt.mcap");
        TraceLogs.Expected x = TraceLogs.writeFile(TraceLogs.tracesDir().resolve("pioneer-laser-sonar.gt.trace.jsonl"),
                log, Map.of());
        byte[] file = Files.readAllBytes(log);
        assertArrayEquals(Mcap.MAGIC, Arrays.copyOf(file, 8));
        assertArrayEquals(Mcap.MAGIC, Arrays.copyOfRange(file, file.length - 8, file.length));
        String text = new String(file, StandardCharsets.ISO_8859_1);
        assertTrue(text.contains("zstd"));
        // a Player laser header would appear uncompressed if chunks were not compressed
        byte[] someFrame = x.wire.stream().filter(e -> e.event() instanceof WireEvent.Frame f && f.wireSize() > 1000)
                .findFirst().orElseThrow().event().bytes();
        assertFalse(text.contains(new String(someFrame, 0, 200, StandardCharsets.ISO_8859_1)), "payload bytes stored raw");
        assertTrue(file.length * 2 < x.rawBytes, file.length + " bytes for " + x.rawBytes + " raw");
    }

    // --- seeking ---------------------------------------------------------------------------------

    private Path smallChunkLog(String traceName, int chunkSize) throws IOException {
        Path log = tmp.resolve(traceName + "." + chunkSize + ".mcap");
        try (SpyLogWriter w = SpyLogWriter.create(FileChannel.open(log, StandardOpenOption.CREATE,
                StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE), Map.of("k", "v"), chunkSize)) {
            TraceLogs.write(TraceLogs.tracesDir().resolve(traceName), w);
        }
        return log;
    }

    @Test
    void entriesFromStartsAtTheFirstEntryAtOrAfterTheTimeAndReadsNoEarlierChunk() throws IOException {
        Path log = smallChunkLog("pioneer-laser-sonar.sonar.trace.jsonl", 16 * 1024);
        List<LogEntry> everything;
        try (SpyLogReader r = SpyLogReader.open(log)) {
            everything = all(r.entries());
            assertTrue(r.chunkCount() > 20, "chunks: " + r.chunkCount());
        }
        for (int pick : new int[] { 0, 1, everything.size() / 3, everything.size() / 2, everything.size() - 1 }) {
            long t = everything.get(pick).timeNanos() + (pick % 2); // also between two entries' times
            int first = 0;
            while (first < everything.size() && everything.get(first).timeNanos() < t) {
                first++;
            }
            try (SpyLogReader r = SpyLogReader.open(log)) {
                List<LogEntry> from = all(r.entriesFrom(t));
                assertEquals(everything.size() - first, from.size(), "from " + t);
                for (int i = 0; i < from.size(); i++) {
                    assertSameEntry(everything.get(first + i), from.get(i));
                }
                assertEquals(chunksEndingAtOrAfter(log, t), r.chunksRead(), "from " + t);
                if (pick >= everything.size() / 2) {
                    assertTrue(r.chunksRead() < r.chunkCount() * 3 / 4, r.chunksRead() + " of " + r.chunkCount());
                }
            }
        }
        assertTrue(all(SpyLogReader.open(log).entriesFrom(Long.MAX_VALUE)).isEmpty());
    }

    /** How many chunks hold an entry at or after t (read with a reader of its own). */
    private static int chunksEndingAtOrAfter(Path log, long t) throws IOException {
        int n = 0;
        try (SpyLogReader r = SpyLogReader.open(log)) {
            for (long[] span : r.chunkSpans()) {
                if (r.chunkEntries(span[0]).stream().anyMatch(e -> e.timeNanos() >= t)) {
                    n++;
                }
            }
        }
        return n;
    }

    @Test
    void aCorruptEarlyChunkIsSkippedAndReportedAndSeekingPastItReadsNothingOfIt() throws IOException {
        Path log = smallChunkLog("pioneer-laser-sonar.sonar.trace.jsonl", 16 * 1024);
        List<LogEntry> everything;
        long[] firstChunk;
        try (SpyLogReader r = SpyLogReader.open(log)) {
            everything = all(r.entries());
            firstChunk = r.chunkSpans().get(0);
        }
        try (FileChannel f = FileChannel.open(log, StandardOpenOption.WRITE)) {
            f.write(ByteBuffer.wrap(new byte[64]), firstChunk[0] + firstChunk[1] / 2); // zeroes inside the compressed data
        }
        long t = everything.get(everything.size() / 2).timeNanos();
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertFalse(r.recovered(), "the summary is intact");
            List<LogEntry> from = all(r.entriesFrom(t));
            assertEquals(t, from.get(0).timeNanos());
            assertSameEntry(everything.get(everything.size() - 1), from.get(from.size() - 1));
            assertEquals(List.of(), r.damage(), "seeking past the damaged chunk does not read it");
            List<LogEntry> read = all(r.entries());
            assertTrue(read.size() < everything.size(), "the damaged chunk's entries are missing");
            assertSameEntry(everything.get(everything.size() - 1), read.get(read.size() - 1));
            assertEquals(1, r.damage().size(), r.damage().toString());
            String d = r.damage().get(0);
            assertTrue(d.contains("chunk 0") && d.contains("bytes " + firstChunk[0] + "..")
                    && d.contains("; " + (everything.size() - read.size()) + " messages lost"), d);
            assertEquals(1, r.skippedChunks());
        }
    }

    @Test
    void logTimesNeverGoBackInFileOrderAndPublishTimesAreTheCaptureTimes() throws IOException {
        Path log = tmp.resolve("overlap.mcap");
        byte[] frame = frameBytes(8);
        List<Long> captured = new ArrayList<>();
        try (SpyLogWriter w = SpyLogWriter.create(FileChannel.open(log, StandardOpenOption.CREATE,
                StandardOpenOption.WRITE), Map.of(), 1 << 20)) {
            // connection 1's messages reach the writer late (captured at 10..19, after 100..109 were written)
            for (int i = 0; i < 10; i++) {
                w.wire(100 + i, 2, 6666, Direction.CLIENT_TO_SERVER, i * 48L, LogEntry.Kind.FRAME, frame, null);
                captured.add(100L + i);
            }
            w.flush();
            for (int i = 0; i < 10; i++) {
                w.wire(10 + i, 1, 6665, Direction.CLIENT_TO_SERVER, i * 48L, LogEntry.Kind.FRAME, frame, null);
                captured.add(10L + i);
            }
            w.flush();
            w.wire(50, 1, 6665, Direction.SERVER_TO_CLIENT, 0, LogEntry.Kind.BANNER, new byte[32], null);
            captured.add(50L);
        }
        List<Long> logTimes = new ArrayList<>();
        List<Long> publishTimes = new ArrayList<>();
        try (org.stagecraft.mcap.McapReader m = org.stagecraft.mcap.McapReader.open(log)) {
            for (org.stagecraft.mcap.ChunkInfo c : m.chunks()) {
                m.readChunk(c, msg -> {
                    logTimes.add(msg.logTime());
                    publishTimes.add(msg.publishTime());
                });
            }
        }
        assertEquals(captured, publishTimes, "the capture times, exactly");
        for (int i = 1; i < logTimes.size(); i++) {
            assertTrue(logTimes.get(i) >= logTimes.get(i - 1), "log time " + i + " goes back: " + logTimes);
            assertTrue(logTimes.get(i) >= publishTimes.get(i), "logged before it was captured: " + i);
        }
        assertEquals(109L, logTimes.get(10), "a late entry is logged at the previous entry's log time");
        try (SpyLogReader r = SpyLogReader.open(log)) {
            List<LogEntry> entries = all(r.entries());
            assertEquals(21, entries.size());
            assertTimeOrder(entries);
            assertEquals(100, entries.get(0).timeNanos());
            assertEquals(10 * 48, r.streamBytes(1, Direction.CLIENT_TO_SERVER).length);
            assertEquals(10 * 48, r.streamBytes(2, Direction.CLIENT_TO_SERVER).length);
        }
    }

    private static byte[] frameBytes(int payload) {
        byte[] b = new byte[40 + payload];
        b[39] = (byte) payload; // size field, big-endian, last header word
        return b;
    }

    // --- crashes ---------------------------------------------------------------------------------

    @Test
    void aLogCutOffAnywhereKeepsEveryCompleteChunkAndNothingGarbled() throws IOException {
        Path log = smallChunkLog("requests.reqclient.trace.jsonl", 8 * 1024);
        byte[] file = Files.readAllBytes(log);
        List<long[]> spans;
        List<LogEntry> everything;
        List<Integer> perChunk = new ArrayList<>();
        try (SpyLogReader r = SpyLogReader.open(log)) {
            spans = r.chunkSpans();
            everything = all(r.entries());
            for (long[] s : spans) {
                perChunk.add(r.chunkEntries(s[0]).size());
            }
        }
        assertTrue(spans.size() > 10, "chunks: " + spans.size());
        Random random = new Random(42);
        List<Integer> cuts = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            cuts.add(8 + random.nextInt(file.length - 8));
        }
        cuts.add((int) (spans.get(3)[0] + spans.get(3)[1])); // exactly after a chunk
        cuts.add((int) (spans.get(3)[0] + spans.get(3)[1] - 1)); // one byte short of it
        cuts.add(file.length - 1);
        for (int cut : cuts) {
            Path part = tmp.resolve("cut-" + cut + ".mcap");
            Files.write(part, Arrays.copyOf(file, cut));
            int complete = 0;
            int expected = 0;
            for (int i = 0; i < spans.size(); i++) {
                if (spans.get(i)[0] + spans.get(i)[1] <= cut) {
                    complete++;
                    expected += perChunk.get(i);
                }
            }
            try (SpyLogReader r = SpyLogReader.open(part)) {
                assertTrue(r.recovered(), "cut at " + cut);
                assertEquals(complete, r.chunkCount(), "cut at " + cut);
                assertEquals(Map.of("k", "v"), r.metadata());
                List<LogEntry> got = all(r.entries());
                assertEquals(expected, got.size(), "cut at " + cut);
                for (int i = 0; i < got.size(); i++) {
                    assertSameEntry(everything.get(i), got.get(i));
                }
                byte[] s2c = r.streamBytes(1, Direction.SERVER_TO_CLIENT);
                byte[] full = SpyLogReader.open(log).streamBytes(1, Direction.SERVER_TO_CLIENT);
                assertArrayEquals(Arrays.copyOf(full, s2c.length), s2c, "a prefix of the stream");
            }
        }
        Files.write(tmp.resolve("tiny.mcap"), Arrays.copyOf(file, 5));
        assertThrows(SpyLogFormatException.class, () -> SpyLogReader.open(tmp.resolve("tiny.mcap")));
    }

    @Test
    void aLogCutOffInsideAChunkTakesItsTimesFromTheRecoveredChunks() throws IOException {
        Path log = smallChunkLog("pioneer-laser-sonar.sonar.trace.jsonl", 16 * 1024);
        List<long[]> spans;
        long fullStart;
        try (SpyLogReader full = SpyLogReader.open(log)) {
            spans = full.chunkSpans();
            fullStart = full.startTimeNanos();
        }
        assertTrue(spans.size() > 3, "chunks: " + spans.size());
        long[] third = spans.get(2);
        Path cut = tmp.resolve("cut-in-chunk.mcap");
        Files.write(cut, Arrays.copyOf(Files.readAllBytes(log), (int) (third[0] + third[1] / 2)));
        try (SpyLogReader r = SpyLogReader.open(cut)) {
            assertTrue(r.recovered());
            assertEquals(2, r.chunkCount());
            List<LogEntry> e = all(r.entries());
            assertFalse(e.isEmpty());
            long max = e.stream().mapToLong(LogEntry::timeNanos).max().getAsLong();
            assertEquals(fullStart, r.startTimeNanos());
            assertEquals(e.get(0).timeNanos(), r.startTimeNanos());
            assertEquals(max, r.endTimeNanos());
            assertTrue(r.endTimeNanos() > r.startTimeNanos());
        }
    }

    @Test
    void aLogWithoutItsFooterIsRecoveredWhole() throws IOException {
        Path log = tmp.resolve("full.mcap");
        TraceLogs.Expected x = TraceLogs.writeFile(TraceLogs.tracesDir().resolve("python-client.sentinel.trace.jsonl"),
                log, Map.of("host", "robot-1"));
        byte[] file = Files.readAllBytes(log);
        Path cut = tmp.resolve("nofooter.mcap");
        Files.write(cut, Arrays.copyOf(file, file.length - MCAP_TAIL));
        try (SpyLogReader full = SpyLogReader.open(log); SpyLogReader r = SpyLogReader.open(cut)) {
            assertFalse(full.recovered());
            assertTrue(r.recovered());
            assertEquals(full.messageCount(), r.messageCount());
            assertEquals(full.eventCount(), r.eventCount());
            assertEquals(full.chunkCount(), r.chunkCount());
            assertEquals(full.startTimeNanos(), r.startTimeNanos());
            assertEquals(full.endTimeNanos(), r.endTimeNanos());
            assertEquals(Map.of("host", "robot-1"), r.metadata());
            assertEquals(full.connections(), r.connections());
            for (TraceLogs.StreamKey k : x.streams.keySet()) {
                assertArrayEquals(x.stream(k.conn(), k.dir()), r.streamBytes(k.conn(), k.dir()));
            }
        }
        // a damaged summary is not trusted either
        byte[] bad = file.clone();
        bad[bad.length - MCAP_TAIL - 20] ^= 0x55; // inside the summary offsets, covered by the summary CRC
        Files.write(cut, bad);
        try (SpyLogReader r = SpyLogReader.open(cut)) {
            assertTrue(r.recovered());
            assertEquals(x.banners + x.frames + x.unframed, r.messageCount());
        }
    }

    @Test
    void aFlushedLogSurvivesTheWriterDying() throws IOException {
        Path log = tmp.resolve("dying.mcap");
        SpyLogWriter w = SpyLogWriter.create(log, Map.of("a", "b"));
        w.connectionOpened(1, 1, "client", "0.0.0.0:6665", "localhost:16665");
        w.wire(2, 1, 6665, Direction.SERVER_TO_CLIENT, 0, LogEntry.Kind.BANNER, new byte[32], null);
        w.flush();
        w.wire(3, 1, 6665, Direction.CLIENT_TO_SERVER, 0, LogEntry.Kind.FRAME, frameBytes(0), null); // never flushed
        // no close(): the process died
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertTrue(r.recovered());
            assertEquals(1, r.messageCount());
            assertEquals(32, r.streamBytes(1, Direction.SERVER_TO_CLIENT).length);
            assertEquals(0, r.streamBytes(1, Direction.CLIENT_TO_SERVER).length);
            assertEquals(List.of(new LogConnection(1, 6665, "client", "0.0.0.0:6665", "localhost:16665", 1, -1, null)),
                    r.connections());
        }
        w.close();
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertFalse(r.recovered());
            assertEquals(2, r.messageCount());
        }
    }

    @Test
    void aFullDiskFailsTheWriterAndLeavesTheLogValidUpToTheLastCompleteChunk() throws IOException {
        Path log = tmp.resolve("full-disk.mcap");
        Random random = new Random(7);
        FillingChannel ch = new FillingChannel(FileChannel.open(log, StandardOpenOption.CREATE, StandardOpenOption.WRITE),
                20_000);
        SpyLogWriter w = SpyLogWriter.create(ch, Map.of("disk", "small"), 1 << 20);
        List<byte[]> written = new ArrayList<>();
        long flushed = 0;
        long offset = 0;
        IOException failure = null;
        for (int i = 0; i < 10_000 && failure == null; i++) {
            byte[] b = new byte[40 + random.nextInt(200)];
            random.nextBytes(b); // incompressible
            try {
                w.wire(i, 1, 6665, Direction.CLIENT_TO_SERVER, offset, LogEntry.Kind.UNFRAMED, b, "garbage " + i);
                written.add(b);
                offset += b.length;
                if (i % 10 == 9) {
                    w.flush();
                    flushed = written.size();
                }
            } catch (IOException e) {
                failure = e;
            }
        }
        assertTrue(failure != null && failure.getMessage().contains("No space"), String.valueOf(failure));
        assertTrue(flushed > 10, "flushed " + flushed);
        IOException again = assertThrows(IOException.class,
                () -> w.wire(1, 1, 6665, Direction.CLIENT_TO_SERVER, 0, LogEntry.Kind.FRAME, frameBytes(0), null));
        assertTrue(again.getMessage().contains("earlier error"), again.getMessage());
        assertThrows(IOException.class, w::flush);
        assertThrows(IOException.class, w::close);
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertTrue(r.recovered());
            assertEquals(Map.of("disk", "small"), r.metadata());
            // every flushed message; the failed write may still have completed its chunk record (the
            // disk filling up in the message indexes after it), which the reader then recovers too
            long chunkAfter = written.size() - flushed;
            assertTrue(r.messageCount() == flushed || r.messageCount() == flushed + chunkAfter,
                    r.messageCount() + " recovered, " + flushed + " flushed");
            List<LogEntry.Wire> got = wires(all(r.entries()));
            assertEquals(r.messageCount(), got.size());
            for (int i = 0; i < got.size(); i++) {
                assertArrayEquals(written.get(i), got.get(i).bytes());
                assertEquals("garbage " + i, got.get(i).reason());
            }
        }
    }

    @Test
    void aFailedWriteToAFileIsCutBackToTheLastCompleteChunk() throws IOException {
        Path log = tmp.resolve("cut-back.mcap");
        // a file that fails after 3000 bytes: the writer truncates the partial chunk away
        FileChannel real = FileChannel.open(log, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
        FileChannel failing = new FillingFile(real, 3000);
        SpyLogWriter w = SpyLogWriter.create(failing, Map.of(), 1 << 20);
        Random random = new Random(1);
        byte[][] noise = new byte[3][1000];
        for (byte[] n : noise) {
            random.nextBytes(n);
        }
        w.wire(1, 1, 6665, Direction.CLIENT_TO_SERVER, 0, LogEntry.Kind.UNFRAMED, noise[0], "x");
        w.flush();
        long good = w.bytesWritten();
        assertTrue(good > 1000 && good < 2000, "one chunk written: " + good);
        w.wire(2, 1, 6665, Direction.CLIENT_TO_SERVER, 1000, LogEntry.Kind.UNFRAMED, noise[1], "x");
        w.wire(3, 1, 6665, Direction.CLIENT_TO_SERVER, 2000, LogEntry.Kind.UNFRAMED, noise[2], "x");
        assertThrows(IOException.class, w::flush);
        assertEquals(good, Files.size(log), "the partial chunk is gone");
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertEquals(1, r.messageCount());
            assertEquals(0, r.skippedChunks());
        }
    }

    // --- content ---------------------------------------------------------------------------------

    @Test
    void metadataEventsDiagnosticsAndUnframedBytesRoundTrip() throws IOException {
        Path log = tmp.resolve("events.mcap");
        Map<String, String> meta = new LinkedHashMap<>();
        meta.put("listen", "6665,6666");
        meta.put("upstream", "16665,16666");
        meta.put("player.cfg", "driver ( name \"stage\" provides [\"simulation:0\"] )\n# äöü ✓");
        meta.put("empty", "");
        try (SpyLogWriter w = SpyLogWriter.create(log, meta)) {
            w.connectionOpened(1000, 3, "127.0.0.1:50000", "0.0.0.0:6666", "localhost:16666");
            w.wire(1001, 3, 6666, Direction.SERVER_TO_CLIENT, new WireEvent.Banner(0, new byte[32]));
            w.wire(1002, 3, 6666, Direction.CLIENT_TO_SERVER, new WireEvent.Unframed(0, new byte[] { 1, 2, 3 }, "corrupt header: bad type 99"));
            w.diagnostic(1003, 3, Direction.CLIENT_TO_SERVER, 3, "laser body does not fit: ranges_count 9999");
            w.diagnostic(1004, 3, null, -1, "upstream refused");
            w.connectionClosed(1005, 3, "client closed");
            assertEquals(2, w.messagesWritten());
            assertEquals(0, w.bytesWritten() - w.bytesWritten()); // stable between calls
        }
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertEquals(meta, r.metadata());
            List<LogEntry> e = all(r.entries());
            assertEquals(6, e.size());
            assertEquals(new LogEntry.Opened(1000, 3, "127.0.0.1:50000", "0.0.0.0:6666", "localhost:16666"), e.get(0));
            LogEntry.Wire banner = (LogEntry.Wire) e.get(1);
            assertEquals(LogEntry.Kind.BANNER, banner.kind());
            assertEquals("", banner.reason());
            LogEntry.Wire unframed = (LogEntry.Wire) e.get(2);
            assertEquals(LogEntry.Kind.UNFRAMED, unframed.kind());
            assertEquals("corrupt header: bad type 99", unframed.reason());
            assertArrayEquals(new byte[] { 1, 2, 3 }, unframed.bytes());
            assertEquals(new LogEntry.Diagnostic(1003, 3, Direction.CLIENT_TO_SERVER, 3,
                    "laser body does not fit: ranges_count 9999"), e.get(3));
            LogEntry.Diagnostic d = (LogEntry.Diagnostic) e.get(4);
            assertNull(d.dir());
            assertEquals("upstream refused", d.text());
            assertEquals(new LogEntry.Closed(1005, 3, "client closed"), e.get(5));
            assertEquals(List.of(new LogConnection(3, 6666, "127.0.0.1:50000", "0.0.0.0:6666", "localhost:16666", 1000,
                    1005, "client closed")), r.connections());
            assertEquals(1000, r.startTimeNanos());
            assertEquals(1005, r.endTimeNanos());
            assertEquals(2, r.messageCount());
            assertEquals(4, r.eventCount());
        }
    }

    @Test
    void anEmptyLogAndANonLogAreTold() throws IOException {
        Path log = tmp.resolve("empty.mcap");
        SpyLogWriter.create(log, Map.of()).close();
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertFalse(r.recovered());
            assertEquals(0, r.messageCount());
            assertFalse(r.entries().hasNext());
            assertEquals(List.of(), r.connections());
            assertEquals(0, r.streamBytes(1, Direction.CLIENT_TO_SERVER).length);
        }
        Path text = tmp.resolve("trace.jsonl");
        Files.writeString(text, "{\"format\":\"player-trace\",\"version\":1}\n");
        SpyLogFormatException e = assertThrows(SpyLogFormatException.class, () -> SpyLogReader.open(text));
        assertTrue(e.getMessage().contains("not an MCAP file"), e.getMessage());
    }
}
