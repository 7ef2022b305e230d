package org.stagecraft.spy.breakpoint;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.eclipse.jdt.annotation.Nullable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldObserver;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.RecordedSession;

/**
 * The Player-to-program gate of robot data breakpoints on recorded traffic, re-chunked at random: every
 * byte goes on unchanged and in order; on a hit, exactly the bytes before the triggering message have
 * gone on, and the rest waits until it is passed on.
 */
class BreakpointGateTest {
    private static final ConnectionInfo CONN = new ConnectionInfo(1, 6665, "127.0.0.1:40000", "127.0.0.1:6665",
            "127.0.0.1:7000");
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());

    /** Laser scans whose nearest return is closer than {@code metres}: the test's own reading, not the field language's. */
    static MessageCondition laserCloserThan(float metres) {
        return new MessageCondition() {
            @Override
            public boolean watches(ConnectionInfo connection, MessageHeader h) {
                return h.interf() == Laser.CODE && h.type() == 1;
            }

            @Override
            public @Nullable Satisfied test(MessageHeader h, byte[] payload) {
                if (DECODER.decode(h, payload).body() instanceof Laser.Scan s) {
                    float min = Float.POSITIVE_INFINITY;
                    for (float f : s.ranges().toArray()) {
                        min = Math.min(min, f);
                    }
                    return min < metres ? new Satisfied("min " + min, java.util.List.of()) : null;
                }
                return null;
            }

            @Override
            public String text() {
                return "laser closer than " + metres;
            }
        };
    }

    /** Offsets of the laser scans closer than {@code metres} in a Player-to-program stream, found by the framer. */
    static List<Long> closeScans(byte[] s2c, float metres) {
        List<Long> out = new ArrayList<>();
        MessageCondition c = laserCloserThan(metres);
        PlayerFramer f = new PlayerFramer(org.stagecraft.player.wire.Direction.SERVER_TO_CLIENT, e -> {
            if (e instanceof org.stagecraft.player.wire.WireEvent.Frame fr && c.watches(CONN, fr.header())
                    && c.test(fr.header(), fr.payload()) != null) {
                out.add(fr.offset());
            }
        });
        f.accept(s2c);
        return out;
    }

    private static final class Recorder implements HoldObserver {
        final List<HoldAction> actions = new CopyOnWriteArrayList<>();

        @Override
        public void action(HoldAction a) {
            actions.add(a);
        }

        @Override
        public void state(HoldState s) {
        }
    }

    /** Feeds {@code data} to the gate in random chunks of 1..max bytes. */
    private static void feed(BreakpointGate gate, byte[] data, long seed, int max) throws IOException {
        Random r = new Random(seed);
        int pos = 0;
        while (pos < data.length) {
            int n = Math.min(data.length - pos, 1 + r.nextInt(max));
            byte[] buf = new byte[n + 7];
            System.arraycopy(data, pos, buf, 3, n); // the relay's buffer is larger than what one read filled
            gate.relay(buf, 3, n);
            pos += n;
        }
        gate.end();
    }

    private static final class Downstream extends ByteArrayOutputStream {
        @Override
        public synchronized int size() {
            return super.size();
        }
    }

    @ParameterizedTest
    @ValueSource(ints = { 1, 7, 40, 1500, 65536 })
    void everyByteGoesOnWhenNothingHolds(int maxChunk) throws IOException {
        byte[] s2c = RecordedSession.streams("pioneer-laser-sonar.gt.trace.jsonl")[1];
        DataBreakpoints bps = new DataBreakpoints(new RobotHold(HoldObserver.NONE), HoldObserver.NONE);
        bps.setEnabled(true);
        bps.add(new DataBreakpoint("never", laserCloserThan(0f)));
        Downstream out = new Downstream();
        feed(bps.attach(CONN, out), s2c, maxChunk, maxChunk);
        assertArrayEquals(s2c, out.toByteArray());
        assertEquals(null, bps.current());
    }

    @ParameterizedTest
    @ValueSource(longs = { 1, 2, 3, 4, 5, 6, 7, 8 })
    void aHitKeepsTheTriggeringMessageAndWhatFollowsUntilPassedOn(long seed) throws Exception {
        byte[] s2c = RecordedSession.streams("pioneer-laser-sonar.gt.trace.jsonl")[1];
        List<Long> close = closeScans(s2c, 1.0f);
        assertFalse(close.isEmpty(), "the recording has no laser scan closer than 1 m");
        RobotHold holds = new RobotHold(HoldObserver.NONE);
        holds.setEnabled(true);
        Recorder log = new Recorder();
        DataBreakpoints bps = new DataBreakpoints(holds, log);
        bps.setEnabled(true);
        bps.passOnBound(Duration.ofMinutes(5)); // only the test passes it on
        bps.add(new DataBreakpoint("near", laserCloserThan(1.0f)));
        Downstream out = new Downstream();
        CompletableFuture<BreakpointHit> hit = new CompletableFuture<>();
        CompletableFuture<Integer> deliveredAtHit = new CompletableFuture<>();
        bps.addListener(h -> {
            deliveredAtHit.complete(out.size());
            hit.complete(h);
        });
        BreakpointGate gate = bps.attach(CONN, out);
        assertNotNull(gate);
        CompletableFuture<Void> relay = CompletableFuture.runAsync(() -> {
            try {
                feed(gate, s2c, seed, 1 + (int) (seed * 97 % 3000));
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        BreakpointHit h = hit.get(30, TimeUnit.SECONDS);
        long first = close.get(0);
        assertEquals(first, h.offset(), "the first scan closer than 1 m");
        assertEquals(first, (long) deliveredAtHit.get(), "exactly the bytes before the triggering message went on");
        assertArrayEquals(Arrays.copyOfRange(s2c, (int) first, (int) first + h.message().length), h.message());
        assertTrue(holds.isHeld() && holds.reasons().containsKey(HoldReason.DATA_BREAKPOINT), holds.description());
        assertFalse(relay.isDone(), "the relay waits at the breakpoint");
        assertEquals(first, out.size(), "nothing went on while the hit waited");

        h.passOn("the test looked");
        relay.get(30, TimeUnit.SECONDS);
        assertArrayEquals(s2c, out.toByteArray(), "every byte went on, unchanged and in order");
        assertEquals("the test looked", h.passedOnWhy());
        assertEquals(List.of(HoldEntry.Action.BREAK, HoldEntry.Action.PASSED_ON), log.actions.stream().map(HoldAction::kind).toList());
        assertEquals(first, log.actions.get(0).programOffset());
        assertTrue(holds.isHeld(), "the robots stay held until resume");

        bps.resume();
        assertFalse(holds.isHeld(), holds.description());
        assertEquals(null, bps.current());
    }

    @Test
    void withoutAnyonePassingOnTheBoundLetsTheMessagesGo() throws Exception {
        byte[] s2c = RecordedSession.streams("pioneer-laser-sonar.gt.trace.jsonl")[1];
        Recorder log = new Recorder();
        DataBreakpoints bps = new DataBreakpoints(new RobotHold(HoldObserver.NONE), log);
        bps.setEnabled(true);
        bps.passOnBound(Duration.ofMillis(50));
        bps.add(new DataBreakpoint("near", laserCloserThan(1.0f)));
        Downstream out = new Downstream();
        feed(bps.attach(CONN, out), s2c, 11, 4096); // returns: nobody passes on, the bound does
        assertArrayEquals(s2c, out.toByteArray());
        BreakpointHit h = bps.current();
        assertNotNull(h);
        assertTrue(h.passedOnWhy() != null && h.passedOnWhy().contains("not suspended within 50 ms"), h.passedOnWhy());
        assertTrue(h.heldNanos() >= 50_000_000L, "held " + h.heldNanos() + " ns");
        assertEquals(2, log.actions.size(), "one hit while it was open: " + log.actions);
    }

    @Test
    void hitCountStopsAtTheNthAndDisablesTheBreakpoint() throws Exception {
        byte[] s2c = RecordedSession.streams("pioneer-laser-sonar.gt.trace.jsonl")[1];
        List<Long> close = closeScans(s2c, 1.0f);
        assertTrue(close.size() >= 3);
        DataBreakpoints bps = new DataBreakpoints(new RobotHold(HoldObserver.NONE), HoldObserver.NONE);
        bps.setEnabled(true);
        bps.passOnBound(Duration.ZERO);
        bps.add(new DataBreakpoint("third", laserCloserThan(1.0f), true, 3));
        List<BreakpointHit> hits = new CopyOnWriteArrayList<>();
        bps.addListener(h -> {
            hits.add(h);
            bps.resume(); // at once: the breakpoint is tested again
        });
        feed(bps.attach(CONN, new Downstream()), s2c, 5, 2000);
        assertEquals(1, hits.size());
        assertEquals(close.get(2), hits.get(0).offset());
        assertTrue(hits.get(0).disabledByHitCount());
        assertFalse(bps.breakpoints().get(0).enabled());
    }

    @Test
    void untilFalseStopsAgainOnlyAfterTheConditionStoppedHolding() throws Exception {
        byte[] s2c = RecordedSession.streams("pioneer-laser-sonar.gt.trace.jsonl")[1];
        List<Long> close = closeScans(s2c, 1.0f);
        // the first scan nearer than 1 m after one that was not: where an edge-triggered breakpoint stops again
        List<Long> all = new ArrayList<>();
        PlayerFramer f = new PlayerFramer(org.stagecraft.player.wire.Direction.SERVER_TO_CLIENT, e -> {
            if (e instanceof org.stagecraft.player.wire.WireEvent.Frame fr && fr.header().interf() == Laser.CODE
                    && fr.header().type() == 1 && DECODER.decode(fr.header(), fr.payload()).body() instanceof Laser.Scan) {
                all.add(fr.offset());
            }
        });
        f.accept(s2c);
        long again = -1;
        boolean wasFar = false;
        for (long o : all) {
            boolean near = close.contains(o);
            if (o > close.get(0) && wasFar && near) {
                again = o;
                break;
            }
            wasFar = !near && o > close.get(0);
        }
        assertTrue(again > 0, "the recording goes near, away and near again");
        DataBreakpoints bps = new DataBreakpoints(new RobotHold(HoldObserver.NONE), HoldObserver.NONE);
        bps.setEnabled(true);
        bps.passOnBound(Duration.ZERO);
        bps.untilFalse(true);
        bps.add(new DataBreakpoint("near", laserCloserThan(1.0f)));
        List<Long> hits = new CopyOnWriteArrayList<>();
        bps.addListener(h -> {
            hits.add(h.offset());
            bps.resume();
        });
        feed(bps.attach(CONN, new Downstream()), s2c, 9, 3000);
        assertEquals(close.get(0), hits.get(0));
        assertEquals(again, hits.get(1), "stopped again at the first near scan after a far one, not at the next near one");
    }

    @Test
    void offByDefaultAndArmedOnlyWithAnEnabledBreakpoint() throws IOException {
        DataBreakpoints bps = new DataBreakpoints(new RobotHold(HoldObserver.NONE), HoldObserver.NONE);
        assertEquals(null, bps.attach(CONN, new Downstream()), "off: the relay keeps its plain byte copy");
        bps.setEnabled(true);
        assertFalse(bps.armed());
        bps.add(new DataBreakpoint("off", laserCloserThan(1.0f), false, 0));
        assertFalse(bps.armed());
        bps.add(new DataBreakpoint("on", laserCloserThan(1.0f)));
        assertTrue(bps.armed());
        bps.remove("on");
        assertFalse(bps.armed());
    }
}
