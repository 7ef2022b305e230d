package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.fields.FlatFields;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;

/** export and replay from the command line, the replay with a real socket client. */
class ExportAndReplayCommandsTest {
    private static final Path TRACE = TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl");

    /**
     * Threads for the command and its clients: the common pool can have a single thread on a small
     * machine, and a command waiting for clients that cannot run would never end.
     */
    private static final java.util.concurrent.ExecutorService THREADS = java.util.concurrent.Executors.newVirtualThreadPerTaskExecutor();

    @TempDir
    Path tmp;


    private static CommandRun run(String... args) {
        return CommandRun.of(args);
    }

    /** What the export should report, counted from the decoded trace rather than written down. */
    private record TraceFacts(long laserData, String firstScanColumns, long playerSynchs, String playerVersion) {
        static TraceFacts of(Path trace) throws IOException {
            CodecRegistry registry = CodecRegistry.standard();
            long laserData = 0;
            long synchs = 0;
            String columns = null;
            String version = null;
            try (SessionLog log = SessionLogs.open(trace); LogCursor c = log.cursor(Long.MIN_VALUE)) {
                for (LogMessage m = c.next(); m != null; m = c.next()) {
                    if (m.kind() == LogMessage.Kind.BANNER && m.dir() == Direction.SERVER_TO_CLIENT && version == null) {
                        version = new String(m.bytes(), StandardCharsets.US_ASCII).replace("\0", "").trim()
                                .replaceFirst("^Player v\\.", "");
                    }
                    if (m.kind() != LogMessage.Kind.FRAME) {
                        continue;
                    }
                    MessageHeader h = m.decoded().header();
                    String iface = registry.interfaceName(h.interf());
                    if ("laser".equals(iface) && h.messageType() == MessageType.DATA) {
                        laserData++;
                        if (columns == null) {
                            columns = String.join(",", FlatFields.flatten(m.decoded().body()).keySet());
                        }
                    }
                    if ("player".equals(iface) && h.messageType() == MessageType.SYNCH && m.dir() == Direction.SERVER_TO_CLIENT) {
                        synchs++;
                    }
                }
            }
            return new TraceFacts(laserData, columns, synchs, version);
        }
    }

    @Test
    void exportWritesEachFormatAndSaysWhatIsWrong() throws IOException {
        TraceFacts facts = TraceFacts.of(TRACE);
        assertTrue(facts.laserData() > 0 && facts.playerSynchs() > 0 && facts.playerVersion() != null, facts.toString());
        CommandRun csv = run("export", TRACE.toString(), "--format", "csv", "--stream", "dev=laser type=DATA");
        assertEquals(0, csv.code(), csv.err());
        List<String> lines = csv.out().lines().toList();
        assertTrue(lines.get(0).startsWith("time,conn,dir,iface,index,type,subtype,size,timestamp," + facts.firstScanColumns()),
                lines.get(0));
        assertEquals(facts.laserData(), lines.size() - 1, "one row per laser data message of the trace");
        assertTrue(csv.err().contains(facts.laserData() + " rows"), csv.err());

        Path wl = tmp.resolve("gt.log");
        CommandRun w = run("export", TRACE.toString(), "--format", "writelog", "--out", wl.toString());
        assertEquals(0, w.code(), w.err());
        assertTrue(Files.readString(wl).startsWith("## Player version " + facts.playerVersion() + " \n"),
                Files.readString(wl).lines().findFirst().orElse(""));
        assertTrue(w.err().contains("skipped " + facts.playerSynchs() + " x player SYNCH OK:"), w.err());

        // the writelog export opens like any log: export it again, as MCAP
        Path mcap = tmp.resolve("gt.mcap");
        CommandRun m = run("export", wl.toString(), "--format", "mcap", "--out", mcap.toString());
        assertEquals(0, m.code(), m.err());
        assertTrue(Files.size(mcap) > 100_000);

        CommandRun noOut = run("export", TRACE.toString(), "--format", "mcap");
        assertEquals(2, noOut.code());
        assertTrue(noOut.err().contains("--format mcap needs --out FILE"), noOut.err());
        CommandRun badFormat = run("export", TRACE.toString(), "--format", "xls");
        assertEquals(2, badFormat.code());
        assertTrue(badFormat.err().contains("csv, writelog or mcap"), badFormat.err());
        CommandRun missing = run("export", tmp.resolve("nope.mcap").toString(), "--format", "csv");
        assertEquals(1, missing.code());
        assertTrue(missing.err().contains("nope.mcap: no such file"), missing.err());
        CommandRun badPattern = run("export", TRACE.toString(), "--format", "csv", "--stream", "dev=warpdrive");
        assertEquals(2, badPattern.code());
        assertTrue(badPattern.err().contains("warpdrive"), badPattern.err());
    }

    /** Collects what the command prints and hands out the port it listens on. */
    private static final class Watched extends OutputStream {
        private final ByteArrayOutputStream all = new ByteArrayOutputStream();
        final CompletableFuture<Integer> port = new CompletableFuture<>();

        @Override
        public synchronized void write(int b) {
            all.write(b);
            Matcher m = Pattern.compile("listening on [^ ]+:(\\d+)\\R").matcher(text());
            if (m.find()) {
                port.complete(Integer.parseInt(m.group(1)));
            }
        }

        /** The port, or a failure saying why the command never listened. */
        int awaitPort(CompletableFuture<Integer> code, ByteArrayOutputStream err) throws Exception {
            CompletableFuture.anyOf(port, code).get(30, TimeUnit.SECONDS);
            if (!port.isDone()) {
                throw new AssertionError("the command ended without listening: "
                        + code.handle((c, t) -> t != null ? t.toString() : "code " + c).join() + "; "
                        + err.toString(StandardCharsets.UTF_8));
            }
            return port.get();
        }

        synchronized String text() {
            return all.toString(StandardCharsets.UTF_8);
        }
    }

    @Test
    void replayServesTheRecordedServerStreamToARealClientAndWarnsWhenTheClientDiffers() throws Exception {
        RecordedConnection recorded = RecordedConnection.read(TRACE).get(0);
        for (boolean sameClient : new boolean[] { true, false }) {
            Watched out = new Watched();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            CompletableFuture<Integer> code = CompletableFuture.supplyAsync(() -> Main.run(
                    new String[] { "replay", TRACE.toString(), "--to", "127.0.0.1:0", "--speed", "16" },
                    new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8)), THREADS);
            int port = out.awaitPort(code, err);
            byte[] received;
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
                OutputStream o = s.getOutputStream();
                o.write(sameClient ? recorded.clientBytes() : "not what the robot program said".getBytes(StandardCharsets.UTF_8));
                InputStream in = s.getInputStream();
                received = in.readAllBytes();
            }
            assertArrayEquals(recorded.serverBytes(), received, "the recorded banner and server stream, byte for byte");
            assertEquals(0, code.get(60, TimeUnit.SECONDS), err.toString(StandardCharsets.UTF_8));
            String errText = err.toString(StandardCharsets.UTF_8);
            if (sameClient) {
                assertTrue(out.text().contains("exactly what the recorded robot program sent"), out.text());
                assertEquals("", errText);
            } else {
                assertTrue(errText.contains("warning:") && errText.contains("first difference at byte 0"), errText);
            }
            assertTrue(out.text().contains("recorded port 6665 (1 connection) listening on 127.0.0.1:" + port), out.text());
        }
    }

    /** Connects, sends the recorded client bytes and reads until the server closes. */
    private static CompletableFuture<byte[]> client(int port, byte[] send) throws IOException {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        return CompletableFuture.supplyAsync(() -> {
            try (s) {
                s.getOutputStream().write(send);
                return s.getInputStream().readAllBytes();
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }, THREADS);
    }

    @Test
    void replayServesTwoRecordedConnectionsOfOnePortToTwoClientsEachItsOwnBytes() throws Exception {
        Path sonar = TraceCorpus.file("pioneer-laser-sonar.sonar.trace.jsonl");
        List<RecordedConnection> recorded = RecordedConnection.read(sonar);
        assertEquals(2, recorded.size(), "the sonar trace has two clients on one port");
        assertTrue(!java.util.Arrays.equals(recorded.get(0).serverBytes(), recorded.get(1).serverBytes()),
                "the two connections differ, so a mix-up would show");
        Watched out = new Watched();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        CompletableFuture<Integer> code = CompletableFuture.supplyAsync(() -> Main.run(
                new String[] { "replay", sonar.toString(), "--to", "6665=127.0.0.1:0", "--speed", "64" },
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8)), THREADS);
        int port = out.awaitPort(code, err);
        // the n-th client accepted gets the port's n-th recorded connection: connect one after the other
        CompletableFuture<byte[]> first = client(port, recorded.get(0).clientBytes());
        CompletableFuture<byte[]> second = client(port, recorded.get(1).clientBytes());
        assertArrayEquals(recorded.get(0).serverBytes(), first.get(60, TimeUnit.SECONDS), "first client: connection 1's server bytes");
        assertArrayEquals(recorded.get(1).serverBytes(), second.get(60, TimeUnit.SECONDS), "second client: connection 2's server bytes");
        assertEquals(0, code.get(60, TimeUnit.SECONDS), err.toString(StandardCharsets.UTF_8));
        assertEquals("", err.toString(StandardCharsets.UTF_8));
        assertTrue(out.text().contains("recorded port 6665 (2 connections) listening on 127.0.0.1:" + port), out.text());
        assertEquals(2, Pattern.compile("exactly what the recorded robot program sent").matcher(out.text()).results().count(),
                out.text());
    }

    /** A stand-in connection: the mapping looks at ports only. */
    private record Port(int port) implements org.stagecraft.recording.play.PlayableConnection {
        @Override
        public int conn() {
            return port;
        }

        @Override
        public double length() {
            return 0;
        }

        @Override
        public org.stagecraft.recording.play.ChunkSource openServer() {
            return org.stagecraft.recording.play.ChunkSource.of(List.of());
        }

        @Override
        public org.stagecraft.recording.play.ChunkSource openClient() {
            return openServer();
        }
    }

    @Test
    void toMapsAGivenRecordedPortAndTheRestInTheLogsOrder() throws IOException {
        java.util.Map<Integer, List<Port>> byPort = new java.util.LinkedHashMap<>();
        byPort.put(6665, List.of(new Port(6665)));
        byPort.put(6666, List.of(new Port(6666), new Port(6666)));
        List<org.stagecraft.recording.play.RecordedPlayer.Listener> ls = ReplayCommand.listeners(
                List.of("6666=127.0.0.1:7001", "7000"), byPort);
        assertEquals(2, ls.size());
        assertEquals(6666, ls.get(0).connections().get(0).port(), "PORT= picks the recorded port");
        assertEquals(2, ls.get(0).connections().size());
        assertEquals(7001, ls.get(0).address().getPort());
        assertEquals("127.0.0.1", ls.get(0).address().getHostString());
        assertEquals(6665, ls.get(1).connections().get(0).port(), "a bare address takes the first recorded port in order");
        assertEquals(7000, ls.get(1).address().getPort());
        assertTrue(ls.get(1).address().getAddress().isLoopbackAddress(), "loopback when no host is given");

        IllegalArgumentException twice = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> ReplayCommand.listeners(List.of("6665=127.0.0.1:7001", "6665=127.0.0.1:7002"), byPort));
        assertTrue(twice.getMessage().contains("recorded port 6665 is given twice"), twice.getMessage());
        IllegalArgumentException badPort = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> ReplayCommand.listeners(List.of("6665=127.0.0.1:http"), byPort));
        assertTrue(badPort.getMessage().contains("'http' is not a port number"), badPort.getMessage());
    }

    @Test
    void replaySaysWhichPortIsInUseAndWhichFileIsMissing() throws IOException {
        try (ServerSocket busy = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CommandRun r = run("replay", TRACE.toString(), "--to", "127.0.0.1:" + busy.getLocalPort());
            assertEquals(1, r.code());
            assertTrue(r.err().contains("cannot listen on port " + busy.getLocalPort()), r.err());
        }
        CommandRun missing = run("replay", tmp.resolve("gone.trace.jsonl").toString(), "--to", "127.0.0.1:0");
        assertEquals(1, missing.code());
        assertTrue(missing.err().contains("gone.trace.jsonl: no such file"), missing.err());
        CommandRun noPort = run("replay", TRACE.toString(), "--to", "7000=127.0.0.1:0");
        assertEquals(2, noPort.code());
        assertTrue(noPort.err().contains("no connection to port 7000 (its ports: [6665])"), noPort.err());
        CommandRun tooMany = run("replay", TRACE.toString(), "--to", "127.0.0.1:0", "--to", "127.0.0.1:0");
        assertEquals(2, tooMany.code());
        assertTrue(tooMany.err().contains("only 1 Player port"), tooMany.err());
        CommandRun noTo = run("replay", TRACE.toString());
        assertEquals(2, noTo.code());
    }
}
