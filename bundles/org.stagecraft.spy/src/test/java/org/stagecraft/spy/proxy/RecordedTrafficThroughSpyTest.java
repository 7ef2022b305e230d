package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * Every recorded connection of every shared trace, all at once, through one spy: each recorded
 * connection gets its own port (seven ports), each port two robot programs at the same time. A
 * replay peer plays Player's side, another the program's side; both must see exactly the recorded
 * bytes, the bus must carry exactly what the decoder makes of them, and the log must rebuild every
 * stream. The log is kept under target/test-logs for the CI's independent MCAP check.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RecordedTrafficThroughSpyTest {
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());
    private static final int CLIENTS_PER_PORT = 2;

    /** The Player side of one recorded connection, served to every client that connects. */
    private record FakePlayer(RecordedConnection recorded, ServerSocket socket, List<Future<ReplayPeer.Result>> served) {
    }

    private static List<DecodedMessage> decoded(byte[] stream, Direction dir) {
        List<DecodedMessage> out = new ArrayList<>();
        PlayerFramer framer = new PlayerFramer(dir, e -> {
            if (e instanceof WireEvent.Frame f) {
                out.add(DECODER.decode(f));
            }
        });
        framer.accept(stream);
        framer.end();
        return out;
    }

    @Test
    void everyRecordedConnectionAtOnceIsRelayedPublishedAndLoggedExactly() throws Exception {
        List<RecordedConnection> recorded = new ArrayList<>();
        for (Path trace : TraceCorpus.all()) {
            recorded.addAll(RecordedConnection.read(trace));
        }
        assertTrue(recorded.size() >= 6, "at least six ports' worth of recorded connections");
        Path logFile = Files.createDirectories(Path.of("target", "test-logs")).resolve("recorded-traffic.mcap");

        long expectedMessages = 0;
        for (RecordedConnection rc : recorded) {
            for (Direction dir : Direction.values()) {
                expectedMessages += CLIENTS_PER_PORT * decoded(rc.bytes(dir), dir).size();
            }
        }
        CountDownLatch allPublished = new CountDownLatch(Math.toIntExact(expectedMessages));
        Map<Long, List<SpyMessage>> onBus = new ConcurrentHashMap<>();
        try (ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor(); StreamBus bus = new StreamBus()) {
            Subscription all = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 20), m -> {
                if (m.payload() instanceof SpyMessage sm) {
                    // one subscriber thread delivers in order, so per-stream lists keep wire order
                    onBus.computeIfAbsent(streamOf(sm.connection().id(), sm.dir()), k -> new ArrayList<>()).add(sm);
                    allPublished.countDown();
                }
            });
            List<FakePlayer> players = new ArrayList<>();
            List<Route> routes = new ArrayList<>();
            for (RecordedConnection rc : recorded) {
                ServerSocket s = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
                List<Future<ReplayPeer.Result>> served = new ArrayList<>();
                for (int i = 0; i < CLIENTS_PER_PORT; i++) {
                    served.add(peers.submit(() -> ReplayPeer.serve(s.accept(), rc)));
                }
                players.add(new FakePlayer(rc, s, served));
                routes.add(Route.loopback(0, "127.0.0.1", s.getLocalPort()));
            }
            ObservationPipeline pipeline = new ObservationPipeline(bus, DECODER,
                    new LogRecorder(SpyLogWriter.create(logFile, Map.of("test", getClass().getSimpleName()))), 256L << 20);
            NetworkSpy spy = new NetworkSpy(routes, pipeline);
            Map<Integer, RecordedConnection> byPort = new HashMap<>();
            List<Future<ReplayPeer.Result>> programs = new ArrayList<>();
            try (spy) {
                spy.start();
                for (int r = 0; r < routes.size(); r++) {
                    int port = spy.boundAddresses().get(r).getPort();
                    RecordedConnection rc = players.get(r).recorded();
                    byPort.put(port, rc);
                    for (int i = 0; i < CLIENTS_PER_PORT; i++) {
                        programs.add(peers.submit(() -> ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), rc)));
                    }
                }
                for (Future<ReplayPeer.Result> p : programs) {
                    ReplayPeer.Result result = p.get(120, TimeUnit.SECONDS);
                    assertTrue(result.matches(), "a robot program's bytes differ at " + result.firstDifference());
                }
                for (FakePlayer fp : players) {
                    for (Future<ReplayPeer.Result> f : fp.served()) {
                        ReplayPeer.Result result = f.get(120, TimeUnit.SECONDS);
                        assertTrue(result.matches(), "Player's bytes of connection " + fp.recorded().conn()
                                + " differ at " + result.firstDifference());
                    }
                    fp.socket().close();
                }
            }
            pipeline.close(); // drains: every chunk is framed, published and logged before it returns
            assertTrue(allPublished.await(60, TimeUnit.SECONDS),
                    allPublished.getCount() + " of " + expectedMessages + " messages never reached the subscriber");
            assertEquals(0, all.dropped());

            int connections = recorded.size() * CLIENTS_PER_PORT;
            assertEquals(connections, spy.totalConnections());
            assertEquals(0, pipeline.droppedBytes(), "nothing was lost off the wire at this load");
            assertEquals(0, pipeline.decodeProblems());
            assertEquals(null, pipeline.recorderError());

            // the bus carries, per connection and direction, exactly the decoder's output in order
            try (SpyLogReader log = SpyLogReader.open(logFile)) {
                List<LogConnection> logged = log.connections();
                assertEquals(connections, logged.size());
                for (LogConnection lc : logged) {
                    RecordedConnection rc = byPort.get(lc.port());
                    for (Direction dir : Direction.values()) {
                        byte[] expected = rc.bytes(dir);
                        assertArrayEquals(expected, log.streamBytes(lc.conn(), dir),
                                "the log rebuilds connection " + lc.conn() + " " + dir);
                        List<DecodedMessage> want = decoded(expected, dir);
                        List<SpyMessage> got = onBus.getOrDefault(streamOf(lc.conn(), dir), List.of());
                        assertEquals(want.size(), got.size(), "messages on the bus for connection " + lc.conn() + " " + dir);
                        for (int i = 0; i < want.size(); i++) {
                            assertEquals(want.get(i), got.get(i).message(), "message " + i + " of connection " + lc.conn());
                        }
                    }
                    assertTrue(lc.closed(), "the close of connection " + lc.conn() + " is logged");
                }
                assertEquals(false, log.recovered(), "a cleanly closed log needs no recovery");
            }
        }
    }

    private static long streamOf(int conn, Direction dir) {
        return ((long) conn << 1) | dir.ordinal();
    }
}
