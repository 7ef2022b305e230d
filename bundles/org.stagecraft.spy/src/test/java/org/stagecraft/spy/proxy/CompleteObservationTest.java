package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.AutoClose;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.Cleanup;
import org.stagecraft.streams.StreamBus;

/**
 * Issue 17, item 8: a burst faster than observation is observed completely — the forwarding threads
 * wait for room while observation makes progress, so TCP slows the sender instead of the log losing
 * bytes — and a stuck observation costs the wire at most one wait limit, after which it is dropped
 * from observation as before.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class CompleteObservationTest {
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());
    /** A small bound, so that the recorded session is many times what observation may hold. */
    private static final long BOUND = 256 << 10;
    @AutoClose
    private final Cleanup cleanup = new Cleanup();

    /** A log slower than the wire: every entry costs it {@code costNanos} (a slow disk, a loaded machine). */
    private static final class SlowLog extends ObservationPipelineTest.RecordingRecorder {
        private final long costNanos;
        final AtomicLong entries = new AtomicLong();

        SlowLog(long costNanos) {
            this.costNanos = costNanos;
        }

        @Override
        public void wire(ConnectionInfo c, Direction dir, WireEvent e, long t) throws IOException {
            long until = System.nanoTime() + costNanos;
            while (System.nanoTime() < until) {
                Thread.onSpinWait(); // work, not waiting for anything: the log is simply slow
            }
            entries.incrementAndGet();
            super.wire(c, dir, e, t);
        }
    }

    /** A pipeline with the small bound, on a bus of its own, logging to {@code log}. */
    private ObservationPipeline pipeline(SpyRecorder log) {
        StreamBus bus = new StreamBus();
        cleanup.add(bus);
        ObservationPipeline pipeline = new ObservationPipeline(bus, DECODER, log, BOUND);
        cleanup.add(pipeline);
        return pipeline;
    }

    /** The recorded burst, and a spy observed by the pipeline in front of a Player that replays it. */
    private record Burst(byte[][] rec, NetworkSpy spy, CompletableFuture<byte[]> playerGot) {
        /** Runs the robot program's side through the spy; what it received. */
        byte[] program() throws IOException {
            return RecordedSession.program(spy.boundAddresses().get(0), rec[0]);
        }
    }

    private Burst burst(ObservationPipeline pipeline) throws IOException {
        byte[][] rec = RecordedSession.streams("rates.headless-push.trace.jsonl"); // a headless Stage pushing as fast as it can
        CompletableFuture<byte[]> playerGot = new CompletableFuture<>();
        ServerSocket player = RecordedSession.player(rec[1], playerGot, cleanup);
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", player.getLocalPort())), pipeline);
        cleanup.add(spy);
        spy.start();
        return new Burst(rec, spy, playerGot);
    }

    @Test
    void aBurstFasterThanObservationIsForwardedExactlyAndObservedCompletely() throws Exception {
        SlowLog log = new SlowLog(20_000);
        ObservationPipeline pipeline = pipeline(log);
        Burst b = burst(pipeline);
        byte[][] rec = b.rec();
        assertTrue(rec[1].length > 8 * BOUND, "the burst is many times the observation bound: " + rec[1].length);

        assertArrayEquals(rec[1], b.program(), "the program received Player's bytes exactly");
        assertArrayEquals(rec[0], b.playerGot().get(60, TimeUnit.SECONDS), "Player received the program's bytes exactly");
        assertTrue(log.closedSeen.await(60, TimeUnit.SECONDS), "the connection's close was recorded");

        assertEquals(0, pipeline.droppedBytes(), "nothing forwarded went unobserved");
        assertEquals(0, pipeline.stalls(), "observation was slow, never stuck");
        assertTrue(pipeline.waitedForObservation().toNanos() > 0, "the wire was paced by observation");
        assertArrayEquals(rec[1], log.bytes(Direction.SERVER_TO_CLIENT), "the log has every byte Player sent");
        assertArrayEquals(rec[0], log.bytes(Direction.CLIENT_TO_SERVER), "the log has every byte the program sent");
        assertTrue(pipeline.heldBytes() <= BOUND, "observation holds at most its bound: " + pipeline.heldBytes());
    }

    @Test
    void bestEffortObservationNeverWaitsAndCountsWhatItLeftOut() throws Exception {
        SlowLog log = new SlowLog(20_000);
        ObservationPipeline pipeline = pipeline(log).observationWait(Duration.ZERO);
        Burst b = burst(pipeline);
        byte[][] rec = b.rec();

        assertArrayEquals(rec[1], b.program());
        assertArrayEquals(rec[0], b.playerGot().get(60, TimeUnit.SECONDS));
        assertTrue(log.closedSeen.await(60, TimeUnit.SECONDS));
        assertEquals(Duration.ZERO, pipeline.waitedForObservation(), "best effort: the wire never waited");
        assertTrue(pipeline.droppedBytes() > 0, "a log this slow could not take the burst: " + pipeline.droppedBytes());
        long logged = log.bytes(Direction.SERVER_TO_CLIENT).length + log.bytes(Direction.CLIENT_TO_SERVER).length;
        assertEquals(rec[0].length + rec[1].length, logged + pipeline.droppedBytes(),
                "every forwarded byte is either logged or counted as unobserved");
    }

    @Test
    void aStuckObservationCostsTheWireOneWaitLimitThenItIsLeftOut() throws Exception {
        ObservationPipelineTest.HungLog hung = new ObservationPipelineTest.HungLog();
        Duration limit = Duration.ofMillis(300);
        ObservationPipeline pipeline = pipeline(hung).observationWait(limit);
        List<SpyNotice> notices = new java.util.concurrent.CopyOnWriteArrayList<>();
        pipeline.addListener(notices::add);
        Burst b = burst(pipeline);
        byte[][] rec = b.rec();

        assertArrayEquals(rec[1], b.program(), "forwarding completes although observation is stuck");
        assertArrayEquals(rec[0], b.playerGot().get(60, TimeUnit.SECONDS));
        assertTrue(pipeline.droppedBytes() > 0, "what could not be observed is counted");
        assertTrue(pipeline.stalls() >= 1, "the stall was noticed");
        assertTrue(notices.stream().anyMatch(n -> n.kind() == SpyNotice.Kind.OBSERVATION_STALLED
                && n.text().contains("no progress for 0.3 s")), "and said at once: " + notices);
        // each direction's thread waits at most one limit before the stall is noticed; after it, no chunk waits
        // (a margin of one more limit for the scheduling of a loaded machine)
        assertTrue(pipeline.waitedForObservation().compareTo(limit.multipliedBy(2 * 2)) <= 0,
                "the wire waited at most one limit per direction: " + pipeline.waitedForObservation());
        hung.release.countDown();
    }
}
