package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.player.xdr.XdrWriter;
import org.stagecraft.spy.Cleanup;
import org.stagecraft.streams.StreamBus;

/**
 * The spy's observation side under hostile clients (issue 17): stalled 8 MiB messages, garbage, and
 * failures inside observation. In every case the wire stays exact, and a well-behaved robot
 * program's session is observed and logged completely.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ObservationUnderPressureTest {
    @AutoClose
    private final Cleanup cleanup = new Cleanup();

    /** The two byte streams (client to server, server to client) of a one-connection recording. */
    private static byte[][] recorded(String trace) throws IOException {
        return RecordedSession.streams(trace);
    }

    /** A stand-in Player for one well-behaved session: sends the recorded server stream, keeps what it got. */
    private ServerSocket recordedPlayer(byte[] s2c, CompletableFuture<byte[]> received) throws IOException {
        return RecordedSession.player(s2c, received, cleanup);
    }

    /** A stand-in Player that accepts any number of connections and reads whatever they send. */
    private ServerSocket sinkPlayer() throws IOException {
        ServerSocket up = new ServerSocket(0, 500, InetAddress.getLoopbackAddress());
        cleanup.add(up);
        Thread.ofVirtual().start(() -> {
            while (!up.isClosed()) {
                try {
                    Socket s = up.accept();
                    Thread.ofVirtual().start(() -> {
                        try (s; InputStream in = s.getInputStream()) {
                            in.transferTo(java.io.OutputStream.nullOutputStream());
                        } catch (IOException ignored) {
                            // the spy reset it
                        }
                    });
                } catch (IOException closed) {
                    return;
                }
            }
        });
        return up;
    }

    private static Route route(ServerSocket player) {
        return Route.loopback(0, "127.0.0.1", player.getLocalPort());
    }

    /** A robot program replaying the recorded client stream; returns what it received. */
    private static byte[] robotProgram(InetSocketAddress at, byte[] c2s) throws IOException {
        return RecordedSession.program(at, c2s);
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        await(condition, () -> what);
    }

    private static void await(BooleanSupplier condition, java.util.function.Supplier<String> what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out waiting until " + what.get());
            }
            java.util.concurrent.locks.LockSupport.parkNanos(2_000_000); // polls the condition, ~500 times a second
        }
    }

    private static long usedHeapAfterGc() {
        System.gc();
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }

    private static byte[] header(int interf, int type, int subtype, int size) {
        XdrWriter w = new XdrWriter(MessageHeader.SIZE);
        new MessageHeader(0, 0, interf, 0, type, subtype, 1.0, 0, size).write(w);
        return w.toByteArray();
    }

    @Test
    void manyClientsStallingInsideBigMessagesCannotExhaustTheSpysMemory() throws Exception {
        int attackers = 30;
        int sent = 3 << 20; // of an announced 8 MiB payload
        long bound = 16L << 20;
        byte[][] rec = recorded("pioneer-laser-sonar.gt.trace.jsonl");
        PerConnectionRecorder log = new PerConnectionRecorder();
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()), log, bound);
        cleanup.add(pipeline);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = new NetworkSpy(List.of(route(sinkPlayer()), route(recordedPlayer(rec[1], playerGot))), pipeline);
        cleanup.add(spy);
        spy.start();
        long heapBefore = usedHeapAfterGc();

        byte[] payload = new byte[sent];
        new Random(1).nextBytes(payload);
        byte[] announce = header(6, MessageType.DATA.code(), 1, MessageHeader.MAX_PAYLOAD);
        for (int i = 0; i < attackers; i++) {
            Socket s = new Socket();
            cleanup.add(s);
            s.connect(spy.boundAddresses().get(0));
            s.getOutputStream().write(announce);
            s.getOutputStream().write(payload); // ... and stall, the connection left open
        }
        long attack = (long) attackers * (MessageHeader.SIZE + sent);
        long[] maxHeld = {0};
        await(() -> {
            maxHeld[0] = Math.max(maxHeld[0], pipeline.heldBytes());
            return pipeline.droppedBytes() + pipeline.heldBytes() >= attack;
        }, () -> "every stalled byte is held or given up (forwarded " + spy.bytesForwarded(Direction.CLIENT_TO_SERVER)
                + ", dropped " + pipeline.droppedBytes() + ", held " + pipeline.heldBytes() + ", given up "
                + pipeline.abandonedMessages() + " of " + attack + ")");
        long heapGrowth = usedHeapAfterGc() - heapBefore;

        // well-behaved, after the attack and while the attackers still hold their connections
        byte[] robotGot = robotProgram(spy.boundAddresses().get(1), rec[0]);
        assertArrayEquals(rec[1], robotGot, "the robot program saw exactly what Player sent");
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS), "Player saw exactly what the program sent");
        int good = log.awaitClosedOnPort(spy.boundAddresses().get(1).getPort());
        assertArrayEquals(rec[0], log.bytes(good, Direction.CLIENT_TO_SERVER), "the program's side is logged completely");
        assertArrayEquals(rec[1], log.bytes(good, Direction.SERVER_TO_CLIENT), "Player's side is logged completely");
        assertFalse(log.diagnostics(good).stream().anyMatch(d -> d.contains("not observed")), log.diagnostics(good).toString());

        assertTrue(maxHeld[0] <= bound + (1 << 20), "observation held " + maxHeld[0] + " bytes, bound " + bound);
        assertTrue(pipeline.abandonedMessages() >= attackers - 3, "given up: " + pipeline.abandonedMessages());
        assertTrue(pipeline.droppedBytes() >= attack - bound, "counted as unobserved: " + pipeline.droppedBytes());
        // A framer buffer that doubles kept ~4 MiB per attacker (~120 MiB here); the bound keeps 8 MiB.
        assertTrue(heapGrowth < 48L << 20, "the heap grew by " + heapGrowth / 1048576 + " MiB under the attack");
        assertTrue(log.diagnostics().stream().anyMatch(d -> d.contains("was given up")), "the give-ups are in the log");
    }

    @Test
    void aClientSendingGarbageCannotTakeTheOthersObservation() throws Exception {
        byte[][] rec = recorded("pioneer-laser-sonar.gt.trace.jsonl");
        long bound = 8L << 20;
        assertTrue(rec[0].length + rec[1].length < bound / 2, "the session fits in its fair share");
        CountDownLatch release = new CountDownLatch(1);
        CountDownLatch stuck = new CountDownLatch(1);
        // A log that hangs on the garbage (a slow disk): the garbage piles up in the queue meanwhile.
        PerConnectionRecorder log = new PerConnectionRecorder() {
            @Override
            public void wire(ConnectionInfo c, Direction dir, WireEvent e, long t) {
                if (e instanceof WireEvent.Unframed) {
                    stuck.countDown();
                    try {
                        release.await();
                    } catch (InterruptedException ex) {
                        Thread.currentThread().interrupt();
                    }
                }
                super.wire(c, dir, e, t);
            }
        };
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()), log, bound);
        cleanup.add(pipeline);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = new NetworkSpy(List.of(route(sinkPlayer()), route(recordedPlayer(rec[1], playerGot))), pipeline);
        cleanup.add(spy);
        spy.start();

        byte[] garbage = new byte[32 << 20];
        new Random(2).nextBytes(garbage);
        Socket attacker = new Socket();
        cleanup.add(attacker);
        attacker.connect(spy.boundAddresses().get(0));
        attacker.getOutputStream().write(garbage);
        assertTrue(stuck.await(20, TimeUnit.SECONDS));
        await(() -> spy.bytesForwarded(Direction.CLIENT_TO_SERVER) >= garbage.length, "the garbage is forwarded");

        byte[] robotGot = robotProgram(spy.boundAddresses().get(1), rec[0]);
        assertArrayEquals(rec[1], robotGot);
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS));
        assertTrue(pipeline.droppedBytes() > 0, "the garbage filled its share and was dropped from observation");
        release.countDown();

        int good = log.awaitClosedOnPort(spy.boundAddresses().get(1).getPort());
        assertArrayEquals(rec[0], log.bytes(good, Direction.CLIENT_TO_SERVER), "the program's side is logged completely");
        assertArrayEquals(rec[1], log.bytes(good, Direction.SERVER_TO_CLIENT), "Player's side is logged completely");
        assertFalse(log.diagnostics(good).stream().anyMatch(d -> d.contains("not observed")), log.diagnostics(good).toString());
    }

    @Test
    void anErrorInTheLogIsReportedAtOnceCountedAndTheLogClosed() throws Exception {
        byte[][] rec = recorded("requests.reqclient.trace.jsonl");
        AtomicBoolean broken = new AtomicBoolean();
        PerConnectionRecorder log = new PerConnectionRecorder() {
            int writes;

            @Override
            public void wire(ConnectionInfo c, Direction dir, WireEvent e, long t) {
                if (++writes == 10) {
                    broken.set(true);
                    throw new NoClassDefFoundError("org/stagecraft/spy/log/Missing"); // as with no file descriptors left
                }
                super.wire(c, dir, e, t);
            }
        };
        BlockingQueue<SpyNotice> notices = new LinkedBlockingQueue<>();
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()), log, 64L << 20);
        pipeline.addListener(notices::add);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = new NetworkSpy(List.of(route(recordedPlayer(rec[1], playerGot))), pipeline);
        cleanup.add(spy);
        spy.start();

        assertArrayEquals(rec[1], robotProgram(spy.boundAddresses().get(0), rec[0]), "the wire is untouched");
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS));
        SpyNotice n = notices.poll(20, TimeUnit.SECONDS);
        assertNotNull(n, "the failure is reported while the spy runs, not only at the end");
        assertEquals(SpyNotice.Kind.OBSERVATION_FAILED, n.kind());
        assertTrue(n.kind().isFailure());
        assertTrue(n.text().contains("NoClassDefFoundError"), n.text());
        assertTrue(broken.get());
        assertTrue(log.closeCalled, "the log is closed when it fails, keeping what was written");
        assertTrue(pipeline.recorderError().contains("NoClassDefFoundError"), pipeline.recorderError());
        spy.close();
        pipeline.close();
        assertTrue(pipeline.droppedBytes() > 0, "what the failure cost is counted as unobserved");
        assertTrue(pipeline.internalErrors() >= 1);
    }

    @Test
    void anErrorInADecoderIsReportedCountedAndObservationGoesOn() throws Exception {
        byte[][] rec = recorded("pioneer-laser-sonar.gt.trace.jsonl");
        CodecRegistry registry = CodecRegistry.standard();
        AtomicBoolean armed = new AtomicBoolean();
        // laser scans (interface 6, data, subtype 1): a decoder whose class cannot be loaded
        registry.register(6, MessageType.DATA, 1, "scan", in -> {
            if (armed.get()) {
                throw new NoClassDefFoundError("org/stagecraft/player/codec/Missing");
            }
            throw new org.stagecraft.player.xdr.XdrException(0, "not armed");
        });
        BlockingQueue<SpyNotice> notices = new LinkedBlockingQueue<>();
        PerConnectionRecorder log = new PerConnectionRecorder();
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(registry), log, 64L << 20);
        pipeline.addListener(notices::add);
        armed.set(true);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = new NetworkSpy(List.of(route(recordedPlayer(rec[1], playerGot))), pipeline);
        cleanup.add(spy);
        spy.start();

        assertArrayEquals(rec[1], robotProgram(spy.boundAddresses().get(0), rec[0]), "the wire is untouched");
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS));
        SpyNotice n = notices.poll(20, TimeUnit.SECONDS);
        assertNotNull(n, "the failure is reported at once");
        assertTrue(n.text().contains("NoClassDefFoundError"), n.text());
        int conn = log.awaitClosedOnPort(spy.boundAddresses().get(0).getPort());
        spy.close();
        pipeline.close();
        assertTrue(pipeline.droppedBytes() > 0, "the bytes concerned are counted as unobserved");
        assertTrue(pipeline.internalErrors() > 0);
        assertTrue(pipeline.messages() > 0, "observation went on for the other messages");
        assertTrue(log.diagnostics(conn).stream().anyMatch(d -> d.contains("observation failed")), "the log says so too");
        assertTrue(log.closeCalled, "the log was closed properly");
    }

    /** Keeps the wire bytes and diagnostics it is given, per connection and direction. */
    static class PerConnectionRecorder implements SpyRecorder {
        private final Map<String, ByteArrayOutputStream> bytes = new ConcurrentHashMap<>();
        private final Map<Integer, List<String>> diagnostics = new ConcurrentHashMap<>();
        private final Map<Integer, Integer> closedPorts = new ConcurrentHashMap<>();
        volatile boolean closeCalled;

        @Override
        public void opened(ConnectionInfo connection, long timeNanos) {
        }

        @Override
        public void closed(ConnectionInfo connection, long timeNanos, String reason) {
            closedPorts.put(connection.port(), connection.id());
        }

        @Override
        public void wire(ConnectionInfo c, Direction dir, WireEvent event, long timeNanos) {
            bytes.computeIfAbsent(c.id() + "/" + dir, k -> new ByteArrayOutputStream()).writeBytes(event.bytes());
        }

        @Override
        public void diagnostic(ConnectionInfo c, Direction dir, long streamOffset, String text, long timeNanos) {
            diagnostics.computeIfAbsent(c.id(), k -> Collections.synchronizedList(new ArrayList<>())).add(text);
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
            closeCalled = true;
        }

        int awaitClosedOnPort(int port) throws InterruptedException {
            await(() -> closedPorts.containsKey(port), "the connection on port " + port + " is closed in the log");
            return closedPorts.get(port);
        }

        byte[] bytes(int conn, Direction dir) {
            ByteArrayOutputStream b = bytes.get(conn + "/" + dir);
            return b == null ? new byte[0] : b.toByteArray();
        }

        List<String> diagnostics(int conn) {
            return List.copyOf(diagnostics.getOrDefault(conn, List.of()));
        }

        List<String> diagnostics() {
            return diagnostics.values().stream().flatMap(List::stream).toList();
        }
    }
}
