package org.stagecraft.replay.log;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.ConnectionInfo;

class SessionLogsTest {
    @TempDir
    Path tmp;

    static Stream<Path> traces() {
        return TraceCorpus.all().stream();
    }

    /**
     * The wire entries of a log, in order, against the trace framed on its own; the log's times
     * {@code startNanos} later than the trace's (a trace counts from its recorder's start).
     */
    private static void assertSameWire(List<SessionEvent> expected, List<LogMessage> actual, long startNanos) {
        List<LogMessage> wire = actual.stream().filter(m -> m.dir() != null && m.kind() != LogMessage.Kind.DIAGNOSTIC)
                .toList();
        assertEquals(expected.size(), wire.size(), "wire entries");
        for (int i = 0; i < expected.size(); i++) {
            SessionEvent e = expected.get(i);
            LogMessage m = wire.get(i);
            String at = "entry " + i;
            assertEquals(startNanos + Logs.nanos(e.t()), m.timeNanos(), at);
            assertEquals(e.stream().conn(), m.connection().id(), at);
            assertEquals(e.stream().port(), m.connection().port(), at);
            assertEquals(e.stream().dir(), m.dir(), at);
            assertEquals(e.event().offset(), m.streamOffset(), at);
            switch (e.event()) {
                case WireEvent.Banner b -> assertEquals(LogMessage.Kind.BANNER, m.kind(), at);
                case WireEvent.Frame f -> {
                    assertEquals(LogMessage.Kind.FRAME, m.kind(), at);
                    assertEquals(f.header(), m.decoded().header(), at);
                }
                case WireEvent.Unframed u -> assertEquals(LogMessage.Kind.UNFRAMED, m.kind(), at);
            }
            assertArrayEquals(e.event().bytes(), m.bytes(), at);
        }
    }

    @ParameterizedTest
    @MethodSource("traces")
    void aTraceOpensWithEveryMessageInOrder(Path trace) throws IOException {
        List<SessionEvent> expected = Logs.framed(trace);
        try (SessionLog log = SessionLogs.open(trace)) {
            assertEquals(LogFormat.PLAYER_TRACE, log.format());
            assertEquals(trace, log.path());
            assertTrue(log.problems().isEmpty(), () -> log.problems().toString());
            List<LogMessage> all = Logs.all(log);
            // the trace's times plus the date its header says the recording started: real dates, as a spy log has
            long created;
            try (org.stagecraft.recording.trace.TraceReader r = new org.stagecraft.recording.trace.TraceReader(trace)) {
                String date = ((org.stagecraft.recording.trace.TraceRecord.Header) r.next()).fields().get("created");
                java.time.Instant i = java.time.OffsetDateTime.parse(date).toInstant();
                created = i.getEpochSecond() * 1_000_000_000L + i.getNano();
            }
            assertTrue(created > java.time.Instant.parse("2026-01-01T00:00:00Z").getEpochSecond() * 1_000_000_000L,
                    "the corpus was recorded in 2026");
            assertSameWire(expected, all, created);
            assertEquals(all.get(0).timeNanos(), log.startNanos());
            assertEquals(all.get(all.size() - 1).timeNanos(), log.endNanos());
            Set<Integer> conns = new TreeSet<>();
            expected.forEach(e -> conns.add(e.stream().conn()));
            assertEquals(conns, new TreeSet<>(log.connections().stream().map(ConnectionInfo::id).toList()));
            assertTrue(all.stream().filter(m -> m.kind() == LogMessage.Kind.FRAME).noneMatch(LogMessage::isProblem),
                    "every recorded message decodes");
            assertEquals(conns.size(), all.stream().filter(m -> m.kind() == LogMessage.Kind.OPENED).count());
        }
    }

    @Test
    void aSpyLogOpensThroughItsIndexWithTheSameMessages() throws IOException {
        Path trace = Logs.trace(Logs.GT);
        Path spyLog = spyLog(trace, 16 * 1024);
        try (SessionLog fromTrace = SessionLogs.open(trace); SessionLog fromSpy = SessionLogs.open(spyLog)) {
            assertEquals(LogFormat.SPY_LOG, fromSpy.format());
            assertTrue(fromSpy.problems().isEmpty(), () -> fromSpy.problems().toString());
            List<LogMessage> a = Logs.all(fromTrace);
            List<LogMessage> b = Logs.all(fromSpy);
            assertEquals(a.size(), b.size());
            for (int i = 0; i < a.size(); i++) {
                assertTrue(a.get(i).samePlace(b.get(i)), "entry " + i);
                assertArrayEquals(a.get(i).bytes(), b.get(i).bytes(), "entry " + i);
            }
            assertEquals(fromTrace.startNanos(), fromSpy.startNanos());
            assertEquals(fromTrace.endNanos(), fromSpy.endNanos());
        }
    }

    /** Writes a trace into a spy log with small chunks, as the spy would. */
    private Path spyLog(Path trace, int chunkSize) throws IOException {
        Path file = tmp.resolve(trace.getFileName() + ".mcap");
        try (var ch = Files.newByteChannel(file, java.nio.file.StandardOpenOption.CREATE_NEW,
                java.nio.file.StandardOpenOption.WRITE);
                SpyLogWriter w = SpyLogWriter.create(ch, Map.of("test", "yes"), chunkSize)) {
            assertTrue(TraceImport.convert(trace, w).isEmpty());
        }
        return file;
    }

    @Test
    void theCursorWalksBothWaysAcrossChunksAndWindows() throws IOException {
        Path spyLog = spyLog(Logs.trace(Logs.GT), 8 * 1024);
        try (SessionLog log = SessionLogs.open(spyLog)) {
            List<LogMessage> all = Logs.all(log);
            int window = 64;
            assertTrue(all.size() > 10 * window, "the walk must cross many back windows");
            try (LogCursor c = ((SpyLogSession) log).cursor(log.endNanos() + 1, window)) {
                assertNull(c.next(), "past the end");
                for (int i = all.size() - 1; i >= 0; i--) {
                    LogMessage m = c.previous();
                    assertNotNull(m, "previous at " + i);
                    assertTrue(all.get(i).samePlace(m), "walking back, entry " + i);
                }
                assertNull(c.previous(), "before the start");
                assertTrue(all.get(0).samePlace(c.next()));
            }
        }
    }

    @Test
    void randomStepsAndSeeksAgreeWithTheLogOrder() throws IOException {
        Path spyLog = spyLog(Logs.trace(Logs.GT), 4 * 1024);
        try (SessionLog log = SessionLogs.open(spyLog)) {
            List<LogMessage> all = Logs.all(log);
            Random random = new Random(42);
            try (LogCursor c = ((SpyLogSession) log).cursor(log.startNanos(), 50)) {
                int pos = 0; // index of the entry next() returns
                for (int step = 0; step < 3000; step++) {
                    int op = random.nextInt(10);
                    if (op < 4) {
                        LogMessage m = c.next();
                        if (pos == all.size()) {
                            assertNull(m);
                        } else {
                            assertTrue(all.get(pos).samePlace(m), "next at " + pos);
                            pos++;
                        }
                    } else if (op < 8) {
                        LogMessage m = c.previous();
                        if (pos == 0) {
                            assertNull(m);
                        } else {
                            pos--;
                            assertTrue(all.get(pos).samePlace(m), "previous at " + pos);
                        }
                    } else if (op == 8) {
                        int target = random.nextInt(all.size());
                        long t = all.get(target).timeNanos();
                        c.seek(t);
                        pos = firstAtOrAfter(all, t);
                    } else {
                        int target = random.nextInt(all.size());
                        c.seekTo(all.get(target));
                        pos = target;
                    }
                }
            }
        }
    }

    private static int firstAtOrAfter(List<LogMessage> all, long t) {
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).timeNanos() >= t) {
                return i;
            }
        }
        return all.size();
    }

    @Test
    void aSeekLandsOnTheFirstMessageAtOrAfterTheTime() throws IOException {
        try (SessionLog log = SessionLogs.open(spyLog(Logs.trace(Logs.GT), 32 * 1024))) {
            List<LogMessage> all = Logs.all(log);
            LogMessage mid = all.get(all.size() / 2);
            try (LogCursor c = log.cursor(mid.timeNanos() - 1)) {
                LogMessage first = c.next();
                assertTrue(first.timeNanos() >= mid.timeNanos() - 1);
                assertTrue(all.get(firstAtOrAfter(all, mid.timeNanos() - 1)).samePlace(first));
            }
        }
    }

    @Test
    void aCutOffSpyLogOpensWhatIsReadableAndSaysWhereItStopped() throws IOException {
        Path whole = spyLog(Logs.trace(Logs.GT), 16 * 1024);
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = tmp.resolve("cut.mcap");
        Files.write(cut, java.util.Arrays.copyOf(bytes, bytes.length / 2));
        try (SessionLog full = SessionLogs.open(whole); SessionLog log = SessionLogs.open(cut)) {
            assertEquals(1, log.problems().size(), () -> log.problems().toString());
            assertTrue(full.complete());
            assertFalse(log.complete(), "a spy log without its summary may still grow");
            LogProblem p = log.problems().get(0);
            assertTrue(p.text().contains("recovered"), p.text());
            assertEquals(log.endNanos(), p.timeNanos());
            List<LogMessage> part = Logs.all(log);
            List<LogMessage> all = Logs.all(full);
            assertFalse(part.isEmpty());
            assertTrue(part.size() < all.size());
            for (int i = 0; i < part.size(); i++) {
                assertTrue(all.get(i).samePlace(part.get(i)), "recovered entry " + i);
            }
            assertTrue(log.endNanos() < full.endNanos());
        }
    }

    @Test
    void aCutOffTraceOpensWhatIsReadableAndNamesTheLine() throws IOException {
        Path trace = Logs.trace(Logs.GT);
        List<String> lines = Files.readAllLines(trace, StandardCharsets.UTF_8);
        int keep = lines.size() / 3;
        String broken = lines.get(keep).substring(0, lines.get(keep).length() / 2);
        Path cut = tmp.resolve("cut.trace.jsonl");
        List<String> out = new ArrayList<>(lines.subList(0, keep));
        out.add(broken);
        Files.write(cut, out, StandardCharsets.UTF_8);
        try (SessionLog log = SessionLogs.open(cut)) {
            assertEquals(1, log.problems().size());
            assertEquals("line " + (keep + 1), log.problems().get(0).where());
            assertFalse(Logs.all(log).isEmpty());
        }
    }

    @Test
    void aFileThatIsNoLogIsRefusedByName() throws IOException {
        Path f = tmp.resolve("notes.txt");
        Files.writeString(f, "hello\n");
        IOException e = assertThrows(IOException.class, () -> SessionLogs.open(f));
        assertTrue(e.getMessage().contains(f.toString()), e.getMessage());
        IOException missing = assertThrows(IOException.class, () -> SessionLogs.open(tmp.resolve("gone.mcap")));
        assertTrue(missing.getMessage().contains("gone.mcap"), missing.getMessage());
    }

    @Test
    void theHeadAloneTellsTheFormatAsOpeningAFileDoes() throws IOException {
        byte[] trace = Files.readAllBytes(Logs.trace(Logs.GT));
        byte[] head = java.util.Arrays.copyOf(trace, Math.min(trace.length, SessionLogs.HEAD));
        assertEquals(java.util.Optional.of(LogFormat.PLAYER_TRACE), SessionLogs.formatOf(head));
        assertEquals(java.util.Optional.of(LogFormat.WRITELOG),
                SessionLogs.formatOf("## Player version 3.1.1\n".getBytes(StandardCharsets.ISO_8859_1)));
        // a writelog file without the "##" lines Player writes first is still one
        assertEquals(java.util.Optional.of(LogFormat.WRITELOG), SessionLogs.formatOf(
                "# a comment\n\n0.5 0 6665 sonar 0 1 1 1 0.5\n".getBytes(StandardCharsets.ISO_8859_1)));
        assertEquals(java.util.Optional.empty(), SessionLogs.formatOf("[INFO] BUILD SUCCESS\n".getBytes(StandardCharsets.UTF_8)));
        assertEquals(java.util.Optional.empty(), SessionLogs.formatOf(new byte[0]));
        Path unknown = tmp.resolve("build.log");
        Files.writeString(unknown, "[INFO] BUILD SUCCESS\n");
        assertThrows(IOException.class, () -> SessionLogs.formatOf(unknown));
    }

    @Test
    void anImportedTraceLeavesNoTemporaryFileBehind() throws IOException {
        Path trace = Logs.trace(Logs.GT);
        Set<Path> before = tempImports();
        SessionLog log = SessionLogs.open(trace);
        assertEquals(before.size() + 1, tempImports().size());
        log.close();
        assertEquals(before, tempImports());
    }

    private static Set<Path> tempImports() throws IOException {
        try (Stream<Path> s = Files.list(Path.of(System.getProperty("java.io.tmpdir")))) {
            return new TreeSet<>(s.filter(p -> p.getFileName().toString().startsWith("stagecraft-import-")).toList());
        }
    }
}
