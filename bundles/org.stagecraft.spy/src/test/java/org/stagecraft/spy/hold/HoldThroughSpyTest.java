package org.stagecraft.spy.hold;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.RepeatedTest;
import org.junit.jupiter.api.RepetitionInfo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.spy.Cleanup;
import org.stagecraft.spy.hold.ProgramTraffic.Msg;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/**
 * Holds through the real spy over loopback sockets: a scripted fake Player (sends its banner, keeps
 * every byte it receives) and the recorded robot program written in random chunks.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class HoldThroughSpyTest {
    private static final byte[] PROGRAM = ProgramTraffic.program();
    private static final List<Msg> MESSAGES = ProgramTraffic.frame(PROGRAM);

    /** Player's side: its banner, then it only listens; what it got can be awaited byte-exactly. */
    static final class FakePlayer implements AutoCloseable {
        final ServerSocket server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        private final ByteArrayOutputStream got = new ByteArrayOutputStream();
        private boolean ended;
        private final Thread thread;

        FakePlayer() throws IOException {
            thread = Thread.ofPlatform().daemon().start(this::serve);
        }

        private void serve() {
            try (Socket s = server.accept()) {
                OutputStream out = s.getOutputStream();
                out.write(Arrays.copyOf("Player v.3.1.1".getBytes(StandardCharsets.US_ASCII), 32));
                InputStream in = s.getInputStream();
                byte[] buf = new byte[4096];
                for (int n; (n = in.read(buf)) >= 0;) {
                    synchronized (this) {
                        got.write(buf, 0, n);
                        notifyAll();
                    }
                }
            } catch (IOException e) {
                // the test fails on the bytes that did not come
            }
            synchronized (this) {
                ended = true;
                notifyAll();
            }
        }

        int port() {
            return server.getLocalPort();
        }

        /** Waits until Player has received exactly {@code n} bytes so far (more is a failure). */
        synchronized byte[] await(int n) throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (got.size() < n && !ended && System.nanoTime() < deadline) {
                wait(1000);
            }
            return got.toByteArray();
        }

        synchronized byte[] awaitEnd() throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (!ended && System.nanoTime() < deadline) {
                wait(1000);
            }
            return got.toByteArray();
        }

        @Override
        public void close() throws IOException {
            server.close();
        }
    }

    @AutoClose
    private final Cleanup cleanup = new Cleanup();

    private record Setup(FakePlayer player, NetworkSpy spy, ObservationPipeline pipeline, StreamBus bus, Path log,
            List<StreamMessage> holdStream, java.util.concurrent.Semaphore holdStreamIn) {
    }

    private Setup setup(Path dir, boolean enableHolds) throws IOException {
        FakePlayer player = new FakePlayer();
        cleanup.add(player);
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        List<StreamMessage> holdStream = Collections.synchronizedList(new ArrayList<>());
        java.util.concurrent.Semaphore in = new java.util.concurrent.Semaphore(0); // the bus delivers on its own threads
        org.stagecraft.streams.StreamConsumer keep = m -> {
            holdStream.add(m);
            in.release();
        };
        bus.subscribe(StreamPattern.exactly(HoldStreams.STATE), DeliveryPolicy.lossless(10_000), keep);
        bus.subscribe(HoldStreams.injected(), DeliveryPolicy.lossless(10_000), keep);
        bus.subscribe(HoldStreams.heldBack(), DeliveryPolicy.lossless(10_000), keep);
        Path log = dir.resolve("spy.mcap");
        ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()),
                new LogRecorder(SpyLogWriter.create(log, Map.of())), 64 << 20);
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", player.port())), pipeline);
        cleanup.add(spy);
        spy.holds().setEnabled(enableHolds);
        spy.start();
        return new Setup(player, spy, pipeline, bus, log, holdStream, in);
    }

    private static Socket program(NetworkSpy spy) throws IOException {
        InetSocketAddress at = spy.boundAddresses().get(0);
        Socket s = new Socket(at.getAddress(), at.getPort());
        s.setTcpNoDelay(true);
        return s;
    }

    private static void writeChunked(OutputStream out, byte[] b, int from, int to, Random rnd) throws IOException {
        for (int p = from; p < to;) {
            int n = Math.min(to - p, rnd.nextInt(3) == 0 ? 1 : 1 + rnd.nextInt(600));
            out.write(b, p, n);
            out.flush();
            p += n;
        }
    }

    @Test
    void heldThenReleasedRobotProgramThroughTheSpy(@TempDir Path dir) throws Exception {
        Setup s = setup(dir, true);
        List<Msg> cmds = MESSAGES.stream().filter(Msg::motion).toList();
        Msg lastBeforeHold = cmds.get(9);
        int seg1 = lastBeforeHold.end();
        // the hold covers the program's next 40 messages, ending after a request (which Player must get)
        int idx = MESSAGES.indexOf(lastBeforeHold) + 40;
        while (MESSAGES.get(idx).motion()) {
            idx++;
        }
        int seg2 = MESSAGES.get(idx).end();
        Random rnd = new Random(7);

        try (Socket program = program(s.spy())) {
            OutputStream out = program.getOutputStream();
            writeChunked(out, PROGRAM, 0, seg1, rnd);
            assertArrayEquals(Arrays.copyOf(PROGRAM, seg1), s.player().await(seg1));

            s.spy().holds().hold(HoldReason.SUSPENDED);
            // the program is between messages: the zero command is on its way when hold returns
            byte[] zero = Arrays.copyOfRange(PROGRAM, lastBeforeHold.offset(), lastBeforeHold.end());
            Arrays.fill(zero, 40, 64, (byte) 0); // the program's own last command with vx, vy, va zero
            ByteArrayOutputStream expected = new ByteArrayOutputStream();
            expected.write(PROGRAM, 0, seg1);
            expected.write(zero);
            assertArrayEquals(expected.toByteArray(), s.player().await(expected.size()));

            writeChunked(out, PROGRAM, seg1, seg2, rnd);
            int held = 0;
            for (Msg m : MESSAGES) {
                if (m.offset() >= seg1 && m.end() <= seg2) {
                    if (m.motion()) {
                        held++;
                    } else {
                        expected.write(PROGRAM, m.offset(), m.length());
                    }
                }
            }
            assertTrue(held >= 10, "the held span has commands to hold: " + held);
            assertArrayEquals(expected.toByteArray(), s.player().await(expected.size()),
                    "while held: requests pass, motion commands do not");

            s.spy().holds().release(HoldReason.SUSPENDED);
            writeChunked(out, PROGRAM, seg2, PROGRAM.length, rnd);
            program.shutdownOutput();
            expected.write(PROGRAM, seg2, PROGRAM.length - seg2);
            assertArrayEquals(expected.toByteArray(), s.player().awaitEnd(), "released: nothing replayed, the rest as sent");
        }
        s.spy().close();
        s.pipeline().close();
        assertNull(s.pipeline().recorderError());
        try (SpyLogReader r = SpyLogReader.open(s.log())) {
            assertArrayEquals(PROGRAM, r.programBytes(1));
            assertArrayEquals(s.player().awaitEnd(), r.upstreamBytes(1));
            List<HoldEntry> entries = r.holdEntries();
            assertEquals(1, entries.stream().filter(e -> e.action() == HoldEntry.Action.INJECTED).count());
            long heldLogged = entries.stream().filter(e -> e.action() == HoldEntry.Action.HELD_BACK).count();
            assertEquals(held(seg1, seg2), heldLogged);
        }
        // on the bus: enable (not held), hold on, the injection, each held command, hold off
        assertTrue(s.holdStreamIn().tryAcquire((int) (3 + 1 + held(seg1, seg2)), 20, TimeUnit.SECONDS));
        assertEquals(3 + 1 + held(seg1, seg2), s.holdStream().size());
        assertTrue(s.holdStream().stream().anyMatch(m -> m.payload() instanceof HoldState h && h.held()
                && h.description().contains("suspended in the debugger")));
    }

    private static long held(int from, int to) {
        return MESSAGES.stream().filter(m -> m.motion() && m.offset() >= from && m.end() <= to).count();
    }

    @RepeatedTest(8)
    void holdsSwitchedAtRandomWhileTheRelayRunsStillCutOnlyAtBoundaries(RepetitionInfo rep, @TempDir Path dir) throws Exception {
        Setup s = setup(dir, true);
        Random rnd = new Random(11 + rep.getCurrentRepetition());
        RobotHold holds = s.spy().holds();
        try (Socket program = program(s.spy())) {
            OutputStream out = program.getOutputStream();
            for (int p = 0; p < PROGRAM.length;) {
                int n = Math.min(PROGRAM.length - p, rnd.nextInt(3) == 0 ? 1 : 1 + rnd.nextInt(300));
                out.write(PROGRAM, p, n);
                out.flush();
                p += n;
                if (rnd.nextInt(6) == 0) {
                    // mostly racing the relay thread, which may be anywhere in the bytes sent so far; now
                    // and then after it has caught up, so holds surely meet commands (the writer is faster)
                    if (rnd.nextBoolean()) {
                        awaitRelayed(s.spy(), p);
                    }
                    if (holds.isHeld()) {
                        holds.release(HoldReason.EMERGENCY_STOP);
                    } else {
                        holds.hold(HoldReason.EMERGENCY_STOP);
                    }
                }
            }
            holds.releaseAll(HoldReason.EMERGENCY_STOP);
            program.shutdownOutput();
            // closing a socket with Player's banner unread would reset it, and a reset can discard
            // bytes the spy has not read yet: the program stays connected until Player has it all
            s.player().awaitEnd();
        }
        byte[] player = s.player().awaitEnd();
        s.spy().close();
        s.pipeline().close();
        List<Msg> got = ProgramTraffic.frame(player); // whole messages only, or it throws
        try (SpyLogReader r = SpyLogReader.open(s.log())) {
            assertArrayEquals(PROGRAM, r.programBytes(1));
            assertArrayEquals(player, r.upstreamBytes(1), "the log rebuilds what Player got");
            List<HoldEntry> entries = r.holdEntries();
            long injected = entries.stream().filter(e -> e.action() == HoldEntry.Action.INJECTED).count();
            long heldBack = entries.stream().filter(e -> e.action() == HoldEntry.Action.HELD_BACK).count();
            assertTrue(injected > 0 && heldBack > 0, injected + " injected, " + heldBack + " held back");
            for (HoldEntry e : entries) {
                if (e.action() == HoldEntry.Action.HELD_BACK) {
                    Msg m = MESSAGES.stream().filter(x -> x.offset() == e.programOffset()).findFirst().orElseThrow();
                    assertTrue(m.motion());
                    assertArrayEquals(Arrays.copyOfRange(PROGRAM, m.offset(), m.end()), e.bytes());
                } else if (e.action() == HoldEntry.Action.INJECTED) {
                    assertTrue(got.stream().anyMatch(m -> m.offset() == e.upstreamOffset() && m.length() == e.length()),
                            "an injection is one whole message of Player's stream");
                    assertArrayEquals(new double[] { 0, 0, 0 }, ProgramTraffic.vel(e.bytes()));
                }
            }
            assertEquals(PROGRAM.length - entries.stream().filter(e -> e.action() == HoldEntry.Action.HELD_BACK)
                    .mapToInt(HoldEntry::length).sum() + entries.stream().filter(e -> e.action() == HoldEntry.Action.INJECTED)
                    .mapToInt(HoldEntry::length).sum(), player.length);
        }
    }

    /** Waits until the spy has taken {@code n} bytes from the program (a condition, polled). */
    private static void awaitRelayed(NetworkSpy spy, long n) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (spy.bytesForwarded(org.stagecraft.player.wire.Direction.CLIENT_TO_SERVER) < n) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("the spy took only " + spy.bytesForwarded(org.stagecraft.player.wire.Direction.CLIENT_TO_SERVER)
                        + " of " + n + " bytes");
            }
            java.util.concurrent.locks.LockSupport.parkNanos(50_000);
        }
    }

    @Test
    void withHoldsOffTheSpyForwardsEveryByteEvenWhenAskedToHold(@TempDir Path dir) throws Exception {
        Setup s = setup(dir, false);
        try (Socket program = program(s.spy())) {
            OutputStream out = program.getOutputStream();
            writeChunked(out, PROGRAM, 0, PROGRAM.length / 2, new Random(3));
            s.spy().holds().hold(HoldReason.SUSPENDED);
            writeChunked(out, PROGRAM, PROGRAM.length / 2, PROGRAM.length, new Random(4));
            program.shutdownOutput();
            assertArrayEquals(PROGRAM, s.player().awaitEnd()); // before closing: see above
        }
        s.spy().close();
        s.pipeline().close();
        try (SpyLogReader r = SpyLogReader.open(s.log())) {
            assertEquals(List.of(), r.holdEntries().stream().filter(e -> e.conn() != 0).toList());
            assertArrayEquals(PROGRAM, r.upstreamBytes(1));
        }
    }
}
