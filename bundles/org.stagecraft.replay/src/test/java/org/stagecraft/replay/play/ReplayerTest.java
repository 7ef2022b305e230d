package org.stagecraft.replay.play;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Map;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.Logs;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

class ReplayerTest {
    private SessionLog log;
    private List<LogMessage> all;
    /** What the live spy would have published for the log, in order. */
    private List<StreamMessage> expected;
    private StreamBus bus;

    @BeforeEach
    void open() throws IOException {
        log = SessionLogs.open(Logs.trace(Logs.GT));
        all = Logs.all(log);
        expected = all.stream().flatMap(m -> m.toStreamMessage().stream()).toList();
        bus = new StreamBus();
    }

    @AfterEach
    void close() throws IOException {
        bus.close();
        log.close();
    }

    /** Records what arrives on the bus with the clock's time of arrival. */
    private record Arrival(StreamMessage message, long clockTime) {
    }

    private BlockingQueue<Arrival> listen(ReplayClock clock) {
        BlockingQueue<Arrival> q = new LinkedBlockingQueue<>();
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 20), m -> q.add(new Arrival(m, clock.nanoTime())));
        return q;
    }

    private static List<Arrival> take(BlockingQueue<Arrival> q, int n) throws InterruptedException {
        List<Arrival> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Arrival a = q.poll(30, TimeUnit.SECONDS);
            if (a == null) {
                throw new AssertionError("only " + i + " of " + n + " messages arrived");
            }
            out.add(a);
        }
        return out;
    }

    private static void assertSameMessage(StreamMessage want, StreamMessage got, String at) {
        assertEquals(want.key(), got.key(), at);
        assertEquals(want.timeNanos(), got.timeNanos(), at);
        if (want.payload() instanceof SpyMessage w) {
            SpyMessage g = (SpyMessage) got.payload();
            assertEquals(w.streamOffset(), g.streamOffset(), at);
            assertEquals(w.message().header(), g.message().header(), at);
        }
    }

    @Test
    void allPublishedIsWhatAPlayFromStartToEndPublishes() throws Exception {
        List<StreamMessage> got = Replayer.allPublished(log);
        assertEquals(expected.size(), got.size());
        for (int i = 0; i < expected.size(); i++) {
            assertSameMessage(expected.get(i), got.get(i), "message " + i);
        }
    }

    @ParameterizedTest
    @ValueSource(doubles = { 1, 0.1, 4, 16 })
    void playPublishesEveryMessageInOrderAtTheRecordedPaceScaledBySpeed(double speed) throws Exception {
        ManualClock clock = new ManualClock(false, 1_000_000_000L);
        BlockingQueue<Arrival> arrivals = listen(clock);
        CountDownLatch ended = new CountDownLatch(1);
        try (Replayer r = new Replayer(log, bus, clock)) {
            r.setSpeed(speed);
            r.addListener(new ReplayListener() {
                private boolean started;

                @Override
                public void moved(long timeNanos, LogMessage last) {
                }

                @Override
                public synchronized void stateChanged(boolean playing, double s) {
                    if (playing) {
                        started = true;
                    } else if (started) {
                        ended.countDown();
                    }
                }
            });
            long playedAt = clock.nanoTime();
            r.play();
            List<Arrival> got = take(arrivals, expected.size());
            assertTrue(ended.await(30, TimeUnit.SECONDS), "play stops at the end of the log");
            assertFalse(r.playing());
            for (int i = 0; i < expected.size(); i++) {
                assertSameMessage(expected.get(i), got.get(i).message(), "message " + i);
            }
            List<Long> deadlines = clock.deadlines();
            assertEquals(all.size(), deadlines.size(), "one wait per log message");
            for (int i = 0; i < all.size(); i++) {
                long due = playedAt + (long) ((all.get(i).timeNanos() - log.startNanos()) / speed);
                assertEquals(due, deadlines.get(i), "message " + i + " due at its scaled time");
            }
            assertEquals(log.endNanos(), r.position());
        }
    }

    @Test
    void atOneTimesSpeedOnTheSystemClockTheRecordedGapsAreKept() throws Exception {
        ReplayClock clock = ReplayClock.system();
        // the first two seconds of the session are enough to see pacing and short enough for a test
        long until = log.startNanos() + 2_000_000_000L;
        int n = (int) all.stream().filter(m -> m.timeNanos() <= until).count();
        BlockingQueue<long[]> published = new LinkedBlockingQueue<>(); // log time, clock time
        try (Replayer r = new Replayer(log, bus, clock)) {
            // measured on the play thread right after each publish, not at a consumer of the bus,
            // so the figure is the replayer's pacing and not the bus's delivery
            r.addListener(new ReplayListener() {
                @Override
                public void moved(long timeNanos, LogMessage last) {
                    if (last != null) {
                        published.add(new long[] { last.timeNanos(), clock.nanoTime() });
                    }
                }

                @Override
                public void stateChanged(boolean playing, double speed) {
                }
            });
            long start = clock.nanoTime();
            r.play();
            long worstLate = 0;
            for (int i = 0; i < n; i++) {
                long[] p = published.poll(30, TimeUnit.SECONDS);
                if (p == null) {
                    throw new AssertionError("only " + i + " of " + n + " messages were published");
                }
                long due = start + (p[0] - log.startNanos());
                long late = p[1] - due;
                assertTrue(late >= 0, "message " + i + " came " + (-late) + " ns early");
                worstLate = Math.max(worstLate, late);
            }
            r.pause();
            // generous: a loaded 2-core CI machine may stall a thread; a broken pacer is off by seconds
            assertTrue(worstLate < 250_000_000L, "worst lateness " + worstLate / 1e6 + " ms");
        }
    }

    @Test
    void stepForwardAndBackPublishTheNeighbouringMessages() throws Exception {
        ManualClock clock = new ManualClock(false, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        try (Replayer r = new Replayer(log, bus, clock)) {
            List<LogMessage> stepped = new ArrayList<>();
            for (int i = 0; i < 40; i++) {
                stepped.add(r.stepForward());
            }
            for (int i = 0; i < 40; i++) {
                assertTrue(all.get(i).samePlace(stepped.get(i)), "step " + i);
            }
            assertTrue(all.get(39).samePlace(r.lastPublished()));
            List<LogMessage> back = List.of(r.stepBack(), r.stepBack());
            assertTrue(all.get(38).samePlace(back.get(0)), "a step back shows the message before the one on show");
            assertTrue(all.get(37).samePlace(back.get(1)));
            LogMessage again = r.stepForward();
            assertTrue(all.get(38).samePlace(again), "and a step forward the one after it");
            assertEquals(all.get(38).timeNanos(), r.position());
            List<LogMessage> published = new ArrayList<>(stepped);
            published.addAll(back);
            published.add(again);
            int n = (int) published.stream().filter(m -> m.toStreamMessage().isPresent()).count();
            List<Arrival> got = take(arrivals, n);
            List<StreamMessage> want = published.stream().flatMap(m -> m.toStreamMessage().stream()).toList();
            for (int i = 0; i < n; i++) {
                assertSameMessage(want.get(i), got.get(i).message(), "published " + i);
            }
        }
    }

    @Test
    void atTheStartAStepBackHasNothingToShowAndMovesNothing() throws Exception {
        try (Replayer r = new Replayer(log, bus, new ManualClock(false, 0))) {
            assertNull(r.stepBack(), "nothing before the first message");
            assertTrue(all.get(0).samePlace(r.stepForward()));
            assertNull(r.stepBack(), "the first message stays on show");
            assertTrue(all.get(1).samePlace(r.stepForward()));
            r.seekTo(all.get(100));
            assertNull(r.lastPublished(), "a seek shows nothing");
            assertTrue(all.get(99).samePlace(r.stepBack()), "after a seek a step back shows the message before it");
            assertTrue(all.get(100).samePlace(r.stepForward()));
        }
    }

    @Test
    void seekAfterCountsAMessageAsShownWithoutPublishingIt() throws Exception {
        ManualClock clock = new ManualClock(false, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        try (Replayer r = new Replayer(log, bus, clock)) {
            r.seekAfter(all.get(200));
            assertTrue(all.get(200).samePlace(r.lastPublished()));
            assertEquals(all.get(200).timeNanos(), r.position());
            LogMessage next = r.stepForward();
            assertTrue(all.get(201).samePlace(next), "the next message is the one after it");
            int n = next.toStreamMessage().isPresent() ? 1 : 0;
            take(arrivals, n);
            assertNull(arrivals.poll(100, TimeUnit.MILLISECONDS), "nothing else was published");
        }
    }

    @Test
    void aBrokenListenerDoesNotStopPlay() throws Exception {
        ManualClock clock = new ManualClock(false, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        try (Replayer r = new Replayer(log, bus, clock)) {
            r.addListener(new ReplayListener() {
                @Override
                public void moved(long timeNanos, LogMessage last) {
                    throw new IllegalStateException("a listener with a bug");
                }

                @Override
                public void stateChanged(boolean playing, double speed) {
                }
            });
            r.play();
            take(arrivals, expected.size());
            assertTrue(r.listenerFailures() >= expected.size(), "every call failed and was counted");
            assertNull(r.failure());
        }
    }

    @Test
    void whenReadingFailsPlayStopsAndSaysWhy() throws Exception {
        ManualClock clock = new ManualClock(false, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        CountDownLatch stopped = new CountDownLatch(1);
        try (Replayer r = new Replayer(new BreakingLog(log, 11), bus, clock)) {
            r.addListener(new ReplayListener() {
                @Override
                public void moved(long timeNanos, LogMessage last) {
                }

                @Override
                public void stateChanged(boolean playing, double speed) {
                    if (!playing && r.failure() != null) {
                        stopped.countDown();
                    }
                }
            });
            r.play();
            assertTrue(stopped.await(30, TimeUnit.SECONDS), "play stopped and said so");
            assertFalse(r.playing());
            assertEquals("a decoder bug at message 11", r.failure().getMessage());
            int before = (int) all.subList(0, 10).stream().filter(m -> m.toStreamMessage().isPresent()).count();
            take(arrivals, before);
            assertNull(arrivals.poll(100, TimeUnit.MILLISECONDS), "nothing after the failure");
            assertTrue(all.get(9).samePlace(r.lastPublished()));
        }
    }

    @Test
    void aSeekPublishesOnlyWhatDescribesTheDevicesAndTheNextStepIsTheFirstMessageAfter() throws Exception {
        ManualClock clock = new ManualClock(false, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        try (Replayer r = new Replayer(log, bus, clock)) {
            assertTrue(r.awaitDeviceReplies(30_000));
            LogMessage target = all.get(all.size() / 2);
            seekAndDrain(r, target, arrivals);
            assertEquals(target.timeNanos(), r.position());
            assertNull(arrivals.poll(100, TimeUnit.MILLISECONDS), "a seek publishes no recorded traffic");
            LogMessage next = r.stepForward();
            assertEquals(target.timeNanos(), next.timeNanos());
            LogMessage other = all.get(all.size() / 3);
            r.seekTo(other);
            assertTrue(other.samePlace(r.stepForward()));
            r.seek(Long.MIN_VALUE);
            assertEquals(log.startNanos(), r.position(), "seeks are clamped to the log");
            assertNull(r.stepBack());
            r.seek(Long.MAX_VALUE);
            assertEquals(log.endNanos(), r.position());
        }
    }

    /** The latest reply describing each device (geometry, configuration) before {@code t}, read from the log here. */
    private Map<List<Integer>, LogMessage> deviceRepliesBefore(long t) {
        Map<List<Integer>, LogMessage> latest = new HashMap<>();
        for (LogMessage m : all) {
            if (m.timeNanos() >= t) {
                break;
            }
            if (m.kind() == LogMessage.Kind.FRAME && m.dir() == org.stagecraft.player.wire.Direction.SERVER_TO_CLIENT) {
                var h = m.decoded().header();
                if (h.type() == 4 && h.interf() != 1) { // RESP_ACK of a device interface (not "player")
                    latest.put(List.of(m.connection().id(), h.interf(), h.index(), h.subtype()), m);
                }
            }
        }
        return latest;
    }

    /** Seeks to {@code m} and takes what the seek published: the device replies before it. */
    private void seekAndDrain(Replayer r, LogMessage m, BlockingQueue<Arrival> arrivals) throws Exception {
        assertTrue(r.awaitDeviceReplies(30_000), "the device replies were read");
        r.seekTo(m);
        Map<List<Integer>, LogMessage> want = deviceRepliesBefore(m.timeNanos());
        for (Arrival a : take(arrivals, want.size())) {
            SpyMessage got = (SpyMessage) a.message().payload();
            var h = got.message().header();
            LogMessage w = want.get(List.of(got.connection().id(), h.interf(), h.index(), h.subtype()));
            assertTrue(w != null, "an unexpected message after a seek: " + h);
            assertArrayEquals(PlayerEncoder.encodeBody(w.decoded().body()), PlayerEncoder.encodeBody(got.message().body()),
                    "the device's latest reply before the seek");
        }
    }

    @Test
    void aSeekIntoTheMiddleTellsTheViewsWhereTheSensorsAre() throws Exception {
        ManualClock clock = new ManualClock(false, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        try (Replayer r = new Replayer(log, bus, clock)) {
            LogMessage middle = all.get(all.size() / 2);
            Map<List<Integer>, LogMessage> want = deviceRepliesBefore(middle.timeNanos());
            // the recorded client asked position2d, laser and both rangers (sonar, laser) for their geometry
            assertTrue(want.keySet().stream().map(k -> k.get(1)).collect(java.util.stream.Collectors.toSet())
                    .containsAll(List.of(4, 6, 62)), want.keySet().toString());
            seekAndDrain(r, middle, arrivals);
        }
    }

    @Test
    void pauseStopsPublishingAndPlayGoesOnFromTheSameMessage() throws Exception {
        ManualClock clock = new ManualClock(true, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        int n = pacedPair(100);
        try (Replayer r = new Replayer(log, bus, clock)) {
            seekAndDrain(r, firstWithStream(n), arrivals);
            r.play(); // the first message is due at once
            assertSameMessage(firstWithStreamMessage(n), arrivals.poll(30, TimeUnit.SECONDS).message(), "first played");
            clock.awaitBlocked(1); // waiting for the next message's time
            r.pause();
            assertFalse(r.playing());
            clock.advanceTo(clock.nanoTime() + 60_000_000_000L);
            assertNull(arrivals.poll(200, TimeUnit.MILLISECONDS), "nothing is published while paused");
            long gap = firstWithStream(n + 1).timeNanos() - firstWithStream(n).timeNanos();
            long resumed = clock.nanoTime();
            r.play();
            assertEquals(resumed + gap, clock.awaitBlocked(2), "play goes on paced from where it paused");
            clock.advanceTo(resumed + gap);
            assertSameMessage(firstWithStreamMessage(n + 1), arrivals.poll(30, TimeUnit.SECONDS).message(),
                    "play goes on with the next message");
        }
    }

    @Test
    void aChangeOfSpeedWhilePlayingKeepsTheWaitingMessage() throws Exception {
        ManualClock clock = new ManualClock(true, 0);
        BlockingQueue<Arrival> arrivals = listen(clock);
        int n = pacedPair(200);
        try (Replayer r = new Replayer(log, bus, clock)) {
            seekAndDrain(r, firstWithStream(n), arrivals);
            r.play();
            assertSameMessage(firstWithStreamMessage(n), arrivals.poll(30, TimeUnit.SECONDS).message(), "first");
            long gap = firstWithStream(n + 1).timeNanos() - firstWithStream(n).timeNanos();
            assertEquals(gap, clock.awaitBlocked(1), "due one recorded gap later at 1x");
            r.setSpeed(2);
            assertEquals(gap / 2, clock.awaitBlocked(2), 1, "due half the gap later at 2x");
            clock.advanceTo(gap / 2 + 1);
            assertSameMessage(firstWithStreamMessage(n + 1), arrivals.poll(30, TimeUnit.SECONDS).message(),
                    "the message waiting when the speed changed is the next published");
        }
    }

    /**
     * The first n at or after {@code from} such that stream message n + 1 is the very next log
     * message and comes strictly later (so play has to wait for it).
     */
    private int pacedPair(int from) {
        List<LogMessage> published = all.stream().filter(m -> m.toStreamMessage().isPresent()).toList();
        for (int n = from; n + 1 < published.size(); n++) {
            LogMessage a = published.get(n);
            LogMessage b = published.get(n + 1);
            int ia = indexOf(a);
            if (b.timeNanos() > a.timeNanos() && ia + 1 < all.size() && all.get(ia + 1).samePlace(b)) {
                return n;
            }
        }
        throw new AssertionError("no paced pair after " + from);
    }

    private int indexOf(LogMessage m) {
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).samePlace(m)) {
                return i;
            }
        }
        return -1;
    }

    private LogMessage firstWithStream(int n) {
        return all.stream().filter(m -> m.toStreamMessage().isPresent()).skip(n).findFirst().orElseThrow();
    }

    private StreamMessage firstWithStreamMessage(int n) {
        return firstWithStream(n).toStreamMessage().orElseThrow();
    }

    @Test
    void speedOutsideItsRangeIsRefused() throws IOException {
        try (Replayer r = new Replayer(log, bus, new ManualClock(false, 0))) {
            assertThrows(IllegalArgumentException.class, () -> r.setSpeed(0.05));
            assertThrows(IllegalArgumentException.class, () -> r.setSpeed(17));
            assertThrows(IllegalArgumentException.class, () -> r.setSpeed(Double.NaN));
            r.setSpeed(16);
            assertEquals(16, r.speed());
            assertSame(log, r.log());
        }
    }
}
