package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.WritableByteChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.log.SpyLogWriter;

/** {@code stagecraft spy}: options, the relay with its log, the summary lines, a clean stop. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SpyCommandTest {
    @TempDir
    Path tmp;

    @Test
    void relaysARecordedSessionLogsItAndStopsCleanly() throws Exception {
        RecordedConnection rc = RecordedConnection.read(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl")).get(0);
        Path log = tmp.resolve("session.mcap");
        PrintedLines err = new PrintedLines();
        CountDownLatch stop = new CountDownLatch(1);
        try (ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();
                ServerSocket player = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Future<ReplayPeer.Result> served = threads.submit(() -> ReplayPeer.serve(player.accept(), rc));
            SpyCommand.Options o = SpyCommand.parse(new String[] {"--listen", "0", "--to", "127.0.0.1:" + player.getLocalPort(),
                    "--log", log.toString()});
            Future<Integer> spy = threads.submit(() -> new SpyCommand().serve(o, new PrintStream(err, true, StandardCharsets.UTF_8),
                    stop, false));
            int port = Integer.parseInt(err.await(Pattern.compile("spying 127\\.0\\.0\\.1:(\\d+) -> "), 20_000));

            ReplayPeer.Result program = ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), rc);
            assertTrue(program.matches(), "the program's bytes differ at " + program.firstDifference());
            assertTrue(served.get(20, TimeUnit.SECONDS).matches());
            err.await(Pattern.compile("connections 0 open/(1) \\| .* msg/s \\| .* kB/s \\| undecodable 0 msg \\| unframed 0 B \\| unobserved 0 B"), 20_000);

            stop.countDown();
            assertEquals(0, spy.get(20, TimeUnit.SECONDS));
            assertTrue(err.text().contains("stopped: 1 connections"), err.text());
        }
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertEquals(false, r.recovered(), "the log was closed properly");
            assertArrayEquals(rc.clientBytes(), r.streamBytes(1, Direction.CLIENT_TO_SERVER));
            assertArrayEquals(rc.serverBytes(), r.streamBytes(1, Direction.SERVER_TO_CLIENT));
        }
    }

    /** A disk with room for {@code budget} bytes: a write that does not fit fails whole, like a full disk. */
    private static final class FullDisk implements WritableByteChannel {
        private final FileChannel file;
        private long budget;

        FullDisk(FileChannel file, long budget) {
            this.file = file;
            this.budget = budget;
        }

        @Override
        public int write(ByteBuffer src) throws IOException {
            if (src.remaining() > budget) {
                budget = 0;
                throw new IOException("No space left on device");
            }
            int n = file.write(src);
            budget -= n;
            return n;
        }

        @Override
        public boolean isOpen() {
            return file.isOpen();
        }

        @Override
        public void close() throws IOException {
            file.close();
        }
    }

    @Test
    void aFullDiskStopsTheLogAndTheFinalLineSaysWhatWasRelayedButIsNotInIt() throws Exception {
        RecordedConnection rc = RecordedConnection.read(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl")).get(0);
        Path log = tmp.resolve("full.mcap");
        PrintedLines err = new PrintedLines();
        CountDownLatch stop = new CountDownLatch(1);
        // 8 KiB chunks on a disk with room for 30 kB: the disk fills in the middle of the session
        SpyCommand.LogOpener smallDisk = (file, meta) -> SpyLogWriter.create(new FullDisk(FileChannel.open(file,
                StandardOpenOption.CREATE, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING), 30_000), meta,
                8 << 10);
        try (ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();
                ServerSocket player = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Future<ReplayPeer.Result> served = threads.submit(() -> ReplayPeer.serve(player.accept(), rc));
            SpyCommand.Options o = SpyCommand.parse(new String[] {"--listen", "0", "--to", "127.0.0.1:" + player.getLocalPort(),
                    "--log", log.toString()});
            Future<Integer> spy = threads.submit(() -> new SpyCommand(SpyCommand.FOXGLOVE_SCENE, smallDisk).serve(o,
                    new PrintStream(err, true, StandardCharsets.UTF_8), stop, false));
            int port = Integer.parseInt(err.await(Pattern.compile("spying 127\\.0\\.0\\.1:(\\d+) -> "), 20_000));
            ReplayPeer.Result program = ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), rc);
            assertTrue(program.matches(), "the wire stays exact: the program's bytes differ at " + program.firstDifference());
            assertTrue(served.get(20, TimeUnit.SECONDS).matches(), "the wire stays exact on Player's side");
            err.await(Pattern.compile("connections 0 open/(1) "), 20_000);
            stop.countDown();
            assertEquals(ExitCode.LOSSES, spy.get(20, TimeUnit.SECONDS), "done with losses: the log lacks part of the session");
        }
        long relayed = 0;
        long relayedBytes = 0;
        for (Direction d : Direction.values()) {
            long[] n = new long[2];
            PlayerFramer f = new PlayerFramer(d, e -> {
                n[0]++;
                n[1] += e.bytes().length;
            });
            f.accept(d == Direction.CLIENT_TO_SERVER ? rc.clientBytes() : rc.serverBytes());
            f.end();
            relayed += n[0];
            relayedBytes += n[1];
        }
        long logged = 0;
        long loggedBytes = 0;
        try (SpyLogReader r = SpyLogReader.open(log)) {
            for (Iterator<LogEntry> it = r.entries(); it.hasNext();) {
                if (it.next() instanceof LogEntry.Wire w) {
                    logged++;
                    loggedBytes += w.bytes().length;
                }
            }
        }
        assertTrue(logged > 0 && logged < relayed, "the disk filled in the middle: " + logged + " of " + relayed);
        String last = err.text().lines().filter(l -> l.startsWith("stopped: ")).findFirst().orElse("");
        Matcher m = Pattern.compile("; spy log stopped at \\d+\\.\\d s: No space left on device; (\\d+) messages \\(([^)]+)\\)"
                + " relayed are not in the log$").matcher(last);
        assertTrue(m.find(), "the final line says when, why and what is not in the log: " + last);
        assertEquals(relayed - logged, Long.parseLong(m.group(1)), last);
        long missing = relayedBytes - loggedBytes;
        assertEquals(missing < 1_000_000 ? String.format(Locale.ROOT, "%.1f kB", missing / 1e3)
                : String.format(Locale.ROOT, "%.1f MB", missing / 1e6), m.group(2), missing + " bytes: " + last);
    }

    @Test
    void routesPairListenWithToAndBindLoopbackByDefault() {
        SpyCommand.Options o = SpyCommand.parse(new String[] {"--listen", "6665", "--to", "localhost:7665", "--listen", "6666",
                "--to", "7666", "--log", "x.mcap"});
        assertEquals(2, o.routes().size());
        assertTrue(o.routes().get(0).listen().getAddress().isLoopbackAddress());
        assertEquals(6666, o.routes().get(1).listen().getPort());
        assertEquals("localhost", o.routes().get(0).upstream().getHostString());
        assertEquals(7666, o.routes().get(1).upstream().getPort());
        assertEquals(Path.of("x.mcap"), o.log());
        List<String> bound = List.of("--listen", "6665", "--to", "7665", "--bind", "0.0.0.0");
        assertTrue(SpyCommand.parse(bound.toArray(String[]::new)).routes().get(0).listen().getAddress().isAnyLocalAddress());
    }

    @Test
    void badOptionsAreNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SpyCommand.parse(new String[] {"--listen", "6665"}));
        assertTrue(e.getMessage().contains("1 --listen, 0 --to"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> SpyCommand.parse(new String[] {"--listen", "66x5", "--to", "1"}));
        assertTrue(e.getMessage().contains("66x5"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> SpyCommand.parse(new String[] {"--listen", "6665", "--to", "no-such-host.invalid:7665"}));
        assertTrue(e.getMessage().contains("no-such-host.invalid"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> SpyCommand.parse(new String[] {"--port", "1"}));
        assertTrue(e.getMessage().contains("--port"), e.getMessage());
    }

    @Test
    void aPortInUseIsReportedAndNothingKeepsRunning() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            SpyCommand.Options o = SpyCommand.parse(new String[] {"--listen", String.valueOf(taken.getLocalPort()), "--to", "7665"});
            PrintedLines err = new PrintedLines();
            int code = new SpyCommand().serve(o, new PrintStream(err, true, StandardCharsets.UTF_8), new CountDownLatch(1), false);
            assertEquals(1, code);
            assertTrue(err.text().contains("cannot listen on 127.0.0.1:" + taken.getLocalPort()), err.text());
            assertTrue(err.text().contains("already in use"), err.text());
        }
    }

    private int serveOnce(PrintedLines err, String... args) {
        return new SpyCommand().serve(SpyCommand.parse(args), new PrintStream(err, true, StandardCharsets.UTF_8),
                new CountDownLatch(1), false);
    }

    @Test
    void aPortInUseLeavesNoLogAndAnOldLogUntouched() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            String port = String.valueOf(taken.getLocalPort());
            Path fresh = tmp.resolve("fresh.mcap");
            assertEquals(1, serveOnce(new PrintedLines(), "--listen", port, "--to", "7665", "--log", fresh.toString()));
            assertFalse(Files.exists(fresh), "no empty log is left behind");

            Path old = tmp.resolve("old.mcap");
            Files.writeString(old, "yesterday's session");
            assertEquals(1, serveOnce(new PrintedLines(), "--listen", port, "--to", "7665", "--log", old.toString()));
            assertEquals("yesterday's session", Files.readString(old));
        }
    }

    @Test
    void aLogThatCannotBeWrittenSaysWhy() throws Exception {
        PrintedLines err = new PrintedLines();
        Path missing = tmp.resolve("no-such-folder").resolve("s.mcap");
        assertEquals(1, serveOnce(err, "--listen", "0", "--to", "7665", "--log", missing.toString()));
        assertTrue(err.text().contains("cannot write the log " + missing + ": no such folder " + missing.getParent()),
                err.text());

        PrintedLines err2 = new PrintedLines();
        assertEquals(1, serveOnce(err2, "--listen", "0", "--to", "7665", "--log", tmp.toString()));
        assertTrue(err2.text().contains("cannot write the log " + tmp + ": it is a folder"), err2.text());
    }

    @Test
    void anAddressOfAnotherMachineIsSaidToBeOne() {
        PrintedLines err = new PrintedLines();
        // 192.0.2.1: TEST-NET-1 (RFC 5737), like 8.8.8.8 never an address of this machine
        assertEquals(1, serveOnce(err, "--listen", "0", "--to", "7665", "--bind", "192.0.2.1"));
        assertTrue(err.text().contains("cannot listen on 192.0.2.1:0 (192.0.2.1 is not an address of this machine"),
                err.text());
        assertFalse(err.text().contains("already in use"), err.text());
    }

    @Test
    void aRouteToTheSpyItselfIsRefused() {
        for (String[] args : new String[][] {{"--listen", "6665", "--to", "localhost:6665"},
                {"--listen", "6665", "--to", "127.0.0.1:6665", "--bind", "0.0.0.0"}, {"--listen", "6665", "--to", "6665"}}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SpyCommand.parse(args));
            assertTrue(e.getMessage().contains("leads back to the spy itself"), e.getMessage());
        }
        PrintedLines err = new PrintedLines();
        PrintedLines out = new PrintedLines();
        assertEquals(2, new SpyCommand().run(new String[] {"--listen", "6665", "--to", "6665"},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8)));
        assertTrue(err.text().contains("stagecraft spy: the route 127.0.0.1:6665 -> 127.0.0.1:6665 leads back"), err.text());
    }

    @Test
    void upstreamGraceIsAnOptionInSeconds() {
        assertEquals(Duration.ofSeconds(5), SpyCommand.parse(new String[] {"--listen", "1", "--to", "2"}).upstreamGrace());
        assertEquals(Duration.ofMillis(1500),
                SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--upstream-grace", "1.5"}).upstreamGrace());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--upstream-grace", "soon"}));
        assertTrue(e.getMessage().contains("--upstream-grace 'soon' is not a number of seconds"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--upstream-grace", "-1"}));
        assertTrue(e.getMessage().contains("not 0..3600 seconds"), e.getMessage());
    }

    @Test
    void observationWaitIsAnOptionInSecondsAndZeroMeansBestEffort() {
        assertEquals(Duration.ofSeconds(1), SpyCommand.parse(new String[] {"--listen", "1", "--to", "2"}).observationWait(),
                "complete observation by default");
        assertEquals(Duration.ZERO, SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--observation-wait", "0"})
                .observationWait());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--observation-wait", "forever"}));
        assertTrue(e.getMessage().contains("--observation-wait 'forever' is not a number of seconds"), e.getMessage());
    }

    @Test
    void aRefusalAfterTheGracePeriodIsSaidOnStderr() throws Exception {
        int deadPort;
        try (ServerSocket s = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            deadPort = s.getLocalPort();
        }
        PrintedLines err = new PrintedLines();
        CountDownLatch stop = new CountDownLatch(1);
        try (ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor()) {
            SpyCommand.Options o = SpyCommand.parse(new String[] {"--listen", "0", "--to", "127.0.0.1:" + deadPort,
                    "--upstream-grace", "0.3"});
            Future<Integer> spy = threads.submit(() -> new SpyCommand().serve(o, new PrintStream(err, true, StandardCharsets.UTF_8),
                    stop, false));
            int port = Integer.parseInt(err.await(Pattern.compile("spying 127\\.0\\.0\\.1:(\\d+) -> "), 20_000));
            try (Socket program = new Socket(InetAddress.getLoopbackAddress(), port)) {
                assertThrows(IOException.class, () -> program.getInputStream().read());
            }
            err.await(Pattern.compile("stagecraft spy: Player at 127\\.0\\.0\\.1:" + deadPort
                    + " refused connection (1) from .* for 0\\.3 s; the robot program's connection was closed"), 20_000);
            assertTrue(err.text().contains("refused connection 1 from"), err.text());
            assertTrue(err.text().contains("retrying for up to 0.3 s"), "the wait is said first:\n" + err.text());
            stop.countDown();
            assertEquals(0, spy.get(20, TimeUnit.SECONDS));
        }
    }

    /** Unframed bytes are counted in bytes under one name in the live line and the final line. */
    @Test
    void unframedBytesHaveOneNameAndOneValueLiveAndAtTheEnd() throws Exception {
        byte[] banner = new byte[32];
        byte[] ident = "Player v.3.1.1".getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(ident, 0, banner, 0, ident.length);
        byte[] garbage = new byte[100]; // zeros: no message header has size 0 and type 0
        PrintedLines err = new PrintedLines();
        CountDownLatch stop = new CountDownLatch(1);
        try (ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();
                ServerSocket player = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            threads.submit(() -> {
                try (Socket s = player.accept()) {
                    s.getOutputStream().write(banner);
                    s.getOutputStream().write(garbage);
                    s.shutdownOutput();
                    s.getInputStream().readAllBytes();
                }
                return null;
            });
            SpyCommand.Options o = SpyCommand.parse(new String[] {"--listen", "0", "--to", "127.0.0.1:" + player.getLocalPort()});
            Future<Integer> spy = threads.submit(() -> new SpyCommand().serve(o, new PrintStream(err, true, StandardCharsets.UTF_8),
                    stop, false));
            int port = Integer.parseInt(err.await(Pattern.compile("spying 127\\.0\\.0\\.1:(\\d+) -> "), 20_000));
            try (Socket program = new Socket(InetAddress.getLoopbackAddress(), port)) {
                program.shutdownOutput();
                assertEquals(banner.length + garbage.length, program.getInputStream().readAllBytes().length);
            }
            String live = err.await(Pattern.compile("connections 0 open/1 \\| .* \\| undecodable 0 msg \\| unframed (\\d+) B"),
                    20_000);
            assertEquals(String.valueOf(garbage.length), live);
            stop.countDown();
            assertEquals(0, spy.get(20, TimeUnit.SECONDS));
            assertTrue(err.text().contains("0 undecodable messages, " + garbage.length + " unframed bytes, 0 bytes unobserved"),
                    err.text());
        }
    }
}
