package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.ServerSocket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;
import org.stagecraft.spy.Cleanup;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamConsumer;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/** Recorded Player traffic replayed through a live spy: decoded, published, recorded; and what happens under load. */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ObservationPipelineTest {
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());
    @AutoClose
    private final Cleanup cleanup = new Cleanup();

    private static Path trace(String name) {
        return TraceCorpus.file(name);
    }

    /** The two byte streams of a one-connection recording. */
    private static byte[][] streams(Path trace) throws IOException {
        ByteArrayOutputStream c2s = new ByteArrayOutputStream();
        ByteArrayOutputStream s2c = new ByteArrayOutputStream();
        try (TraceReader r = new TraceReader(trace)) {
            for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                if (rec instanceof TraceRecord.Chunk c && c.stream().conn() == 1) {
                    (c.stream().dir() == Direction.CLIENT_TO_SERVER ? c2s : s2c).writeBytes(c.data());
                }
            }
        }
        return new byte[][] {c2s.toByteArray(), s2c.toByteArray()};
    }

    private static List<WireEvent.Frame> frames(byte[] stream, Direction dir) {
        List<WireEvent.Frame> out = new ArrayList<>();
        org.stagecraft.player.wire.PlayerFramer f = new org.stagecraft.player.wire.PlayerFramer(dir, e -> {
            if (e instanceof WireEvent.Frame fr) {
                out.add(fr);
            }
        });
        f.accept(stream);
        f.end();
        return out;
    }

    /** A stand-in Player: sends the recorded server stream and reads whatever the client sends. */
    private ServerSocket fakePlayer(byte[] s2c, CompletableFuture<byte[]> received) throws IOException {
        return RecordedSession.player(s2c, received, cleanup);
    }

    private ObservationPipeline pipeline(StreamBus bus, SpyRecorder recorder, long maxQueuedBytes) {
        ObservationPipeline pipeline = new ObservationPipeline(bus, DECODER, recorder, maxQueuedBytes);
        cleanup.add(pipeline);
        return pipeline;
    }

    /** A started spy relaying to {@code player} and observing with {@code pipeline}. */
    private NetworkSpy spyInFrontOf(ServerSocket player, ObservationPipeline pipeline) throws IOException {
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", player.getLocalPort())), pipeline);
        cleanup.add(spy);
        spy.start();
        return spy;
    }

    /** A robot program replaying the recorded client stream; returns what it received. */
    private static byte[] robotProgram(NetworkSpy spy, byte[] c2s) throws IOException {
        return RecordedSession.program(spy.boundAddresses().get(0), c2s);
    }

    @Test
    void recordedSessionThroughTheSpyIsForwardedExactlyAndPublishedMessageByMessage() throws Exception {
        byte[][] rec = streams(trace("pioneer-laser-sonar.gt.trace.jsonl"));
        List<WireEvent.Frame> expectedC2S = frames(rec[0], Direction.CLIENT_TO_SERVER);
        List<WireEvent.Frame> expectedS2C = frames(rec[1], Direction.SERVER_TO_CLIENT);
        int expected = expectedC2S.size() + expectedS2C.size();

        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        List<StreamMessage> seen = Collections.synchronizedList(new ArrayList<>());
        CountDownLatch all = new CountDownLatch(expected);
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(expected * 2), m -> {
            if (m.payload() instanceof SpyMessage) {
                seen.add(m);
                all.countDown();
            }
        });
        RecordingRecorder recorder = new RecordingRecorder();
        ObservationPipeline pipeline = pipeline(bus, recorder, 64 << 20);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = spyInFrontOf(fakePlayer(rec[1], playerGot), pipeline);

        byte[] robotGot = robotProgram(spy, rec[0]);
        assertArrayEquals(rec[1], robotGot, "the robot program saw exactly what Player sent");
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS), "Player saw exactly what the program sent");
        assertTrue(all.await(20, TimeUnit.SECONDS), "published " + seen.size() + " of " + expected);

        List<StreamMessage> s2c = seen.stream()
                .filter(m -> ((SpyMessage) m.payload()).dir() == Direction.SERVER_TO_CLIENT).toList();
        assertEquals(expectedS2C.size(), s2c.size());
        for (int i = 0; i < s2c.size(); i++) {
            SpyMessage sm = (SpyMessage) s2c.get(i).payload();
            assertEquals(expectedS2C.get(i).offset(), sm.streamOffset());
            assertArrayEquals(expectedS2C.get(i).bytes(), PlayerEncoder.encode(sm.message()));
            assertEquals(sm.message().header().interf(), s2c.get(i).key().deviceType());
            assertEquals(sm.connection().listen(), s2c.get(i).key().source(), "server messages come from the Player port");
        }
        assertEquals(0, pipeline.decodeProblems());
        assertEquals(0, pipeline.droppedBytes());
        assertTrue(recorder.closedSeen.await(10, TimeUnit.SECONDS));
        assertArrayEquals(rec[1], recorder.bytes(Direction.SERVER_TO_CLIENT), "the log can rebuild the stream");
        assertArrayEquals(rec[0], recorder.bytes(Direction.CLIENT_TO_SERVER));
    }

    @Test
    void aBusConsumerBlockedForeverDelaysNeitherTheWireNorTheLogAndItsLossIsCounted() throws Exception {
        byte[][] rec = streams(trace("pioneer-laser-sonar.gt.trace.jsonl"));
        int expected = frames(rec[0], Direction.CLIENT_TO_SERVER).size() + frames(rec[1], Direction.SERVER_TO_CLIENT).size();
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        CountDownLatch never = new CountDownLatch(1);
        CountDownLatch stuck = new CountDownLatch(2);
        StreamConsumer blockForever = m -> {
            stuck.countDown();
            try {
                never.await(); // a tool that hangs (released only when the bus closes and interrupts it)
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        };
        Subscription lossless = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(100), blockForever);
        Subscription latest = bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), blockForever);
        RecordingRecorder recorder = new RecordingRecorder();
        ObservationPipeline pipeline = pipeline(bus, recorder, 64 << 20);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = spyInFrontOf(fakePlayer(rec[1], playerGot), pipeline);

        assertArrayEquals(rec[1], robotProgram(spy, rec[0]));
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS));
        assertTrue(recorder.closedSeen.await(20, TimeUnit.SECONDS), "the log got everything although tools hang");
        assertArrayEquals(rec[1], recorder.bytes(Direction.SERVER_TO_CLIENT));
        assertTrue(stuck.await(20, TimeUnit.SECONDS), "both consumers are stuck in their first message");
        assertEquals(expected, pipeline.messages(), "every message was published");
        assertEquals(0, pipeline.droppedBytes(), "a hung consumer costs the spy nothing");
        assertTrue(lossless.dropped() >= expected - 1 - 100, "lossless overflow counted: " + lossless.dropped());
        assertTrue(latest.dropped() > 0, "superseded values counted: " + latest.dropped());
    }

    @Test
    void aStuckObserverNeverDelaysTheWireAndTheGapIsReported() throws Exception {
        byte[][] rec = streams(trace("rates.headless-push.trace.jsonl"));
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        List<SpyDiagnostic> diagnostics = Collections.synchronizedList(new ArrayList<>());
        CountDownLatch gapReported = new CountDownLatch(1);
        bus.subscribe(StreamPattern.any().messageType(ObservationPipeline.DIAGNOSTIC_TYPE), DeliveryPolicy.lossless(10_000),
                m -> {
                    SpyDiagnostic d = (SpyDiagnostic) m.payload();
                    diagnostics.add(d);
                    if (d.text().contains("not observed")) {
                        gapReported.countDown();
                    }
                });
        HungLog stuck = new HungLog();
        ObservationPipeline pipeline = pipeline(bus, stuck, 256 * 1024);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = spyInFrontOf(fakePlayer(rec[1], playerGot), pipeline);

        byte[] robotGot = robotProgram(spy, rec[0]); // completes although observation is stuck
        assertArrayEquals(rec[1], robotGot);
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS));
        assertTrue(pipeline.droppedBytes() > 0, "observation had to drop");
        stuck.release.countDown();
        assertTrue(gapReported.await(20, TimeUnit.SECONDS), "the gap is published as a diagnostic: " + diagnostics);
    }

    @Test
    void aFailingLogStopsLoggingVisiblyWhileForwardingAndPublishingGoOn() throws Exception {
        byte[][] rec = streams(trace("requests.reqclient.trace.jsonl"));
        int expected = frames(rec[1], Direction.SERVER_TO_CLIENT).size() + frames(rec[0], Direction.CLIENT_TO_SERVER).size();
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        CountDownLatch all = new CountDownLatch(expected);
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(expected * 2), m -> {
            if (m.payload() instanceof SpyMessage) {
                all.countDown();
            }
        });
        RecordingRecorder full = new RecordingRecorder() {
            int writes;

            @Override
            public void wire(ConnectionInfo c, Direction dir, WireEvent e, long t) throws IOException {
                if (++writes > 10) {
                    throw new IOException("No space left on device");
                }
                super.wire(c, dir, e, t);
            }
        };
        ObservationPipeline pipeline = pipeline(bus, full, 64 << 20);
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        NetworkSpy spy = spyInFrontOf(fakePlayer(rec[1], playerGot), pipeline);
        assertArrayEquals(rec[1], robotProgram(spy, rec[0]));
        assertArrayEquals(rec[0], playerGot.get(20, TimeUnit.SECONDS));
        assertTrue(all.await(20, TimeUnit.SECONDS), "every message is still published");
        assertTrue(pipeline.recorderError().contains("No space left on device"), pipeline.recorderError());
        assertTrue(full.closeCalled, "the log is closed when it fails, keeping what was written");
    }

    /** Keeps the wire events it is given, per direction. */
    static class RecordingRecorder implements SpyRecorder {
        final ByteArrayOutputStream c2s = new ByteArrayOutputStream();
        final ByteArrayOutputStream s2c = new ByteArrayOutputStream();
        final CountDownLatch closedSeen = new CountDownLatch(1);
        volatile boolean closeCalled;

        @Override
        public void opened(ConnectionInfo connection, long timeNanos) {
        }

        @Override
        public void closed(ConnectionInfo connection, long timeNanos, String reason) {
            closedSeen.countDown();
        }

        @Override
        public synchronized void wire(ConnectionInfo connection, Direction dir, WireEvent event, long timeNanos)
                throws IOException {
            (dir == Direction.CLIENT_TO_SERVER ? c2s : s2c).writeBytes(event.bytes());
        }

        @Override
        public void diagnostic(ConnectionInfo connection, Direction dir, long streamOffset, String text, long timeNanos) {
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
            closeCalled = true;
        }

        synchronized byte[] bytes(Direction dir) {
            return (dir == Direction.CLIENT_TO_SERVER ? c2s : s2c).toByteArray();
        }
    }

    /** A log on a disk that hangs: each wire event waits until {@link #release} (or an interrupt). */
    static final class HungLog extends RecordingRecorder {
        final CountDownLatch release = new CountDownLatch(1);

        @Override
        public void wire(ConnectionInfo c, Direction dir, WireEvent e, long t) throws IOException {
            try {
                release.await();
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            }
            super.wire(c, dir, e, t);
        }
    }

}
