package org.stagecraft.spy.hold;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.hold.ProgramTraffic.Msg;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;

/**
 * The message-aware relay under holds, without sockets: the recorded program stream re-chunked at
 * random (many 1-byte chunks), holds switched on and off at random between chunks (so also inside
 * headers and payloads). What Player receives must frame into whole messages, zero commands must land
 * on boundaries, held commands must be exactly the motion commands that began while held, every other
 * byte must pass unchanged and in order, and the log must rebuild both sides.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class HoldingForwarderTest {
    private static final byte[] PROGRAM = ProgramTraffic.program();
    private static final List<Msg> MESSAGES = ProgramTraffic.frame(PROGRAM);
    private static final ConnectionInfo CONN = new ConnectionInfo(1, 6665, "127.0.0.1:40000", "127.0.0.1:6665",
            "127.0.0.1:7665");

    /** Collects what the hold reports, noting in which test-side hold epoch it happened. */
    private static final class Reports implements HoldObserver {
        final List<HoldAction> actions = new ArrayList<>();
        final List<Integer> epochOf = new ArrayList<>();
        final List<HoldState> states = new ArrayList<>();
        int epoch; // counted by the test, not read from the hold
        HoldObserver also = HoldObserver.NONE;

        @Override
        public void action(HoldAction a) {
            actions.add(a);
            epochOf.add(epoch);
            also.action(a);
        }

        @Override
        public void state(HoldState s) {
            states.add(s);
            also.state(s);
        }

        List<HoldAction> of(HoldEntry.Action kind) {
            return actions.stream().filter(a -> a.kind() == kind).toList();
        }
    }

    private static int chunkSize(Random rnd) {
        return switch (rnd.nextInt(10)) {
            case 0, 1, 2 -> 1;
            case 3, 4, 5 -> 2 + rnd.nextInt(40);
            case 6, 7 -> 40 + rnd.nextInt(100);
            default -> 1 + rnd.nextInt(3000);
        };
    }

    /** One run: what Player got, what the hold reported, the hold state each program byte met. */
    private record Run(byte[] player, Reports reports, boolean[] heldAt, List<int[]> epochSpans) {
    }

    private static Run run(long seed, HoldObserver also) throws IOException {
        Random rnd = new Random(seed);
        Reports reports = new Reports();
        reports.also = also;
        RobotHold holds = new RobotHold(reports);
        holds.setEnabled(true);
        ByteArrayOutputStream player = new ByteArrayOutputStream();
        HoldingForwarder f = holds.attach(CONN, player);
        boolean[] heldAt = new boolean[PROGRAM.length];
        List<int[]> spans = new ArrayList<>(); // [from, to] program offsets of each hold
        EnumMap<HoldReason, Integer> model = new EnumMap<>(HoldReason.class);
        HoldReason[] reasons = HoldReason.values();
        int pos = 0;
        while (pos < PROGRAM.length) {
            if (rnd.nextInt(5) == 0) {
                boolean wasHeld = holds.isHeld();
                HoldReason r = reasons[rnd.nextInt(reasons.length)];
                if (!model.isEmpty() && rnd.nextInt(10) < 7) {
                    r = new ArrayList<>(model.keySet()).get(rnd.nextInt(model.size()));
                    assertTrue(holds.release(r));
                    model.computeIfPresent(r, (k, v) -> v == 1 ? null : v - 1);
                } else {
                    if (!wasHeld) {
                        reports.epoch++; // before hold(): its injections belong to the new epoch
                    }
                    holds.hold(r);
                    model.merge(r, 1, Integer::sum);
                }
                assertEquals(!model.isEmpty(), holds.isHeld(), "counted reasons: held while any reason holds");
                if (!wasHeld && holds.isHeld()) {
                    spans.add(new int[] { pos, PROGRAM.length });
                } else if (wasHeld && !holds.isHeld()) {
                    spans.get(spans.size() - 1)[1] = pos;
                }
            }
            int n = Math.min(chunkSize(rnd), PROGRAM.length - pos);
            boolean held = holds.isHeld();
            f.relay(PROGRAM, pos, n);
            Arrays.fill(heldAt, pos, pos + n, held);
            pos += n;
        }
        f.end();
        return new Run(player.toByteArray(), reports, heldAt, spans);
    }

    @Test
    void zeroCommandsLandOnBoundariesAndEverythingElsePassesInOrderUnderRandomChunksAndHolds() throws IOException {
        Set<Integer> boundaries = new HashSet<>();
        for (Msg m : MESSAGES) {
            boundaries.add(m.offset());
        }
        boundaries.add(PROGRAM.length);
        long injectedTotal = 0;
        long heldTotal = 0;
        for (long seed = 1; seed <= 60; seed++) {
            Run run = run(seed, HoldObserver.NONE);
            String at = "seed " + seed;

            // 1. Player's stream is whole Player messages, nothing cut
            List<Msg> got = ProgramTraffic.frame(run.player());

            // 2. injected: zero CMD_VEL, on a program boundary, addressed like the program's last command
            List<HoldAction> injected = run.reports().of(HoldEntry.Action.INJECTED);
            Set<Integer> injectedAtUpstream = new HashSet<>();
            for (HoldAction a : injected) {
                byte[] there = Arrays.copyOfRange(run.player(), (int) a.upstreamOffset(), (int) a.upstreamOffset() + a.length());
                assertArrayEquals(a.bytes(), there, at + ": the injected bytes are where the report says");
                assertTrue(boundaries.contains((int) a.programOffset()), at + ": injected inside a program message at " + a.programOffset());
                MessageHeader h = MessageHeader.read(there, 0);
                assertEquals(4, h.interf());
                assertEquals(2, h.type());
                assertEquals(1, h.subtype());
                assertArrayEquals(new double[] { 0, 0, 0 }, ProgramTraffic.vel(there));
                Msg last = MESSAGES.stream().filter(m -> m.motion() && m.end() <= a.programOffset())
                        .reduce((x, y) -> y).orElseThrow(() -> new AssertionError(at + ": zero command before any program command"));
                assertEquals(last.header().host(), h.host());
                assertEquals(last.header().robot(), h.robot());
                assertEquals(last.header().index(), h.index());
                assertEquals(last.header().timestamp(), h.timestamp());
                injectedAtUpstream.add((int) a.upstreamOffset());
            }

            // 3. held back: exactly the motion commands whose whole header arrived while held
            Set<Integer> expectedHeld = new HashSet<>();
            for (Msg m : MESSAGES) {
                boolean heldThroughHeader = true;
                for (int i = m.offset(); i < m.offset() + MessageHeader.SIZE; i++) {
                    heldThroughHeader &= run.heldAt()[i];
                }
                if (m.motion() && heldThroughHeader) {
                    expectedHeld.add(m.offset());
                }
            }
            Set<Integer> heldOffsets = new HashSet<>();
            for (HoldAction a : run.reports().of(HoldEntry.Action.HELD_BACK)) {
                int o = (int) a.programOffset();
                Msg m = MESSAGES.stream().filter(x -> x.offset() == o).findFirst()
                        .orElseThrow(() -> new AssertionError(at + ": held back from inside a message at " + o));
                assertArrayEquals(Arrays.copyOfRange(PROGRAM, m.offset(), m.end()), a.bytes(), at + ": held back a whole message");
                heldOffsets.add(o);
            }
            assertEquals(expectedHeld, heldOffsets, at);

            // 4. the rest: Player's stream without the injections is the program's without the held
            ByteArrayOutputStream programMinusHeld = new ByteArrayOutputStream();
            for (Msg m : MESSAGES) {
                if (!heldOffsets.contains(m.offset())) {
                    programMinusHeld.write(PROGRAM, m.offset(), m.length());
                }
            }
            ByteArrayOutputStream playerMinusInjected = new ByteArrayOutputStream();
            for (Msg m : got) {
                if (!injectedAtUpstream.contains(m.offset())) {
                    playerMinusInjected.write(run.player(), m.offset(), m.length());
                }
            }
            assertArrayEquals(programMinusHeld.toByteArray(), playerMinusInjected.toByteArray(), at);
            assertEquals(PROGRAM.length - heldBytes(run) + injected.stream().mapToInt(HoldAction::length).sum(), run.player().length);

            // 5. each hold zeroes the (one) device at most once, and does once it can: when a boundary
            //    after the program's first command lies within the hold
            int firstCommandEnd = MESSAGES.stream().filter(Msg::motion).findFirst().orElseThrow().end();
            for (int e = 1; e <= run.epochSpans().size(); e++) {
                int[] span = run.epochSpans().get(e - 1);
                int epoch = e;
                long n = injected.stream().filter(a -> run.reports().epochOf.get(run.reports().actions.indexOf(a)) == epoch).count();
                boolean possible = false;
                for (int b : boundaries) {
                    possible |= b >= span[0] && b <= span[1] && b >= firstCommandEnd;
                }
                assertEquals(possible ? 1 : 0, n, at + ": hold " + e + " over program bytes " + span[0] + ".." + span[1]);
            }
            injectedTotal += injected.size();
            heldTotal += heldOffsets.size();
        }
        System.out.println("random holds: " + injectedTotal + " zero commands injected, " + heldTotal + " commands held back");
        assertTrue(injectedTotal > 300 && heldTotal > 1000, "the runs exercised holds: " + injectedTotal + " injected, "
                + heldTotal + " held back");
    }

    private static int heldBytes(Run run) {
        return run.reports().of(HoldEntry.Action.HELD_BACK).stream().mapToInt(HoldAction::length).sum();
    }

    @Test
    void theLogRebuildsWhatTheProgramSentAndWhatPlayerReceived(@TempDir Path dir) throws Exception {
        for (long seed = 100; seed < 108; seed++) {
            Path file = dir.resolve("hold-" + seed + ".mcap");
            StreamBus bus = new StreamBus();
            // the bus delivers on its own threads: count arrivals, await them
            java.util.concurrent.Semaphore actionsIn = new java.util.concurrent.Semaphore(0);
            java.util.concurrent.Semaphore statesIn = new java.util.concurrent.Semaphore(0);
            bus.subscribe(HoldStreams.injected(), DeliveryPolicy.lossless(100_000), m -> actionsIn.release());
            bus.subscribe(HoldStreams.heldBack(), DeliveryPolicy.lossless(100_000), m -> actionsIn.release());
            bus.subscribe(org.stagecraft.streams.StreamPattern.exactly(HoldStreams.STATE), DeliveryPolicy.lossless(100_000),
                    m -> statesIn.release());
            ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()),
                    new LogRecorder(SpyLogWriter.create(file, Map.of())), 64 << 20);
            long[] t = { 1_000 };
            pipeline.opened(CONN, t[0]++);
            // what the relay does: the observer sees the program's chunk after it was relayed
            Run run = run(seed, new HoldObserver() {
                @Override
                public void action(HoldAction a) {
                    pipeline.holdAction(a, t[0]++);
                }

                @Override
                public void state(HoldState s) {
                    pipeline.holdState(s, t[0]++);
                }
            });
            pipeline.chunk(CONN, Direction.CLIENT_TO_SERVER, PROGRAM.clone(), t[0]++);
            pipeline.closed(CONN, t[0]++, "done");
            pipeline.close();
            assertNull(pipeline.recorderError());
            assertTrue(actionsIn.tryAcquire(run.reports().actions.size(), 20, TimeUnit.SECONDS),
                    "every injection and held-back message is on the bus");
            assertTrue(statesIn.tryAcquire(run.reports().states.size(), 20, TimeUnit.SECONDS));
            bus.close();
            assertEquals(0, actionsIn.availablePermits(), "and nothing more");
            assertEquals(0, statesIn.availablePermits());

            try (SpyLogReader r = SpyLogReader.open(file)) {
                assertArrayEquals(PROGRAM, r.programBytes(1), "seed " + seed + ": the program's bytes, held ones included");
                assertArrayEquals(run.player(), r.upstreamBytes(1), "seed " + seed + ": what Player received");
                List<HoldEntry> entries = r.holdEntries();
                List<HoldEntry> acts = entries.stream().filter(e -> e.conn() == 1).toList();
                assertEquals(run.reports().actions.size(), acts.size());
                for (int i = 0; i < acts.size(); i++) {
                    HoldAction a = run.reports().actions.get(i);
                    assertEquals(a.kind(), acts.get(i).action());
                    assertArrayEquals(a.bytes(), acts.get(i).bytes());
                    assertEquals(a.programOffset(), acts.get(i).programOffset());
                    assertEquals(a.upstreamOffset(), acts.get(i).upstreamOffset());
                    assertFalse(acts.get(i).text().isEmpty());
                }
                long ons = entries.stream().filter(e -> e.action() == HoldEntry.Action.HOLD_ON).count();
                assertEquals(run.reports().states.stream().filter(HoldState::held).count(), ons);
                assertEquals(run.reports().states.size(), entries.stream().filter(e -> e.conn() == 0).count());
                long wire = 0;
                for (var it = r.entries(); it.hasNext();) {
                    if (it.next() instanceof org.stagecraft.spy.log.LogEntry.Wire) {
                        wire++;
                    }
                }
                assertEquals(MESSAGES.size(), wire, "the wire channel holds the program's messages, nothing of Stagecraft's");
            }
        }
    }

    @Test
    void aHoldThatBeginsInsideAMessageInjectsRightAfterIt() throws IOException {
        Msg cmd = MESSAGES.stream().filter(Msg::motion).findFirst().orElseThrow();
        RobotHold holds = new RobotHold(HoldObserver.NONE);
        holds.setEnabled(true);
        ByteArrayOutputStream player = new ByteArrayOutputStream();
        HoldingForwarder f = holds.attach(CONN, player);
        int middle = cmd.offset() + 45; // inside the first CMD_VEL's payload
        f.relay(PROGRAM, 0, middle);
        holds.hold(HoldReason.SUSPENDED);
        assertEquals(middle, player.size(), "nothing injected inside the message the program is sending");
        f.relay(PROGRAM, middle, cmd.end() - middle);
        assertEquals(cmd.end() + 68, player.size(), "the message, then right after it one zero command");
        List<Msg> got = ProgramTraffic.frame(player.toByteArray());
        Msg zero = got.get(got.size() - 1);
        assertEquals(cmd.end(), zero.offset());
        assertArrayEquals(new double[] { 0, 0, 0 }, ProgramTraffic.vel(Arrays.copyOfRange(player.toByteArray(), zero.offset(), zero.end())));
        assertEquals(1, f.injected());
    }

    @Test
    void aHeaderKeptBackWhileHeldGoesOnAtReleaseAndNothingIsReplayed() throws IOException {
        List<Msg> cmds = MESSAGES.stream().filter(Msg::motion).toList();
        Msg first = cmds.get(0);
        Msg second = cmds.get(3);
        RobotHold holds = new RobotHold(HoldObserver.NONE);
        holds.setEnabled(true);
        ByteArrayOutputStream player = new ByteArrayOutputStream();
        HoldingForwarder f = holds.attach(CONN, player);
        f.relay(PROGRAM, 0, first.end());
        holds.hold(HoldReason.EMERGENCY_STOP);
        int zeroEnd = first.end() + 68;
        assertEquals(zeroEnd, player.size(), "program idle between messages: the zero command goes at once");
        // everything up to the second command: its commands held back, the rest forwarded
        f.relay(PROGRAM, first.end(), second.offset() - first.end());
        long heldBetween = cmds.stream().filter(m -> m.offset() > first.offset() && m.offset() < second.offset()).count();
        assertEquals(2, heldBetween);
        assertEquals(heldBetween, f.heldBack());
        int before = player.size();
        f.relay(PROGRAM, second.offset(), 10); // 10 bytes of a header: kept until it says what it is
        assertEquals(before, player.size());
        holds.release(HoldReason.EMERGENCY_STOP);
        assertEquals(before + 10, player.size(), "released: the kept header bytes go on");
        f.relay(PROGRAM, second.offset() + 10, second.length() - 10);
        byte[] p = player.toByteArray();
        assertArrayEquals(Arrays.copyOfRange(PROGRAM, second.offset(), second.end()), Arrays.copyOfRange(p, before, p.length),
                "the program's next command takes effect, and only it: nothing held is replayed");
        assertEquals(1, f.injected());
    }

    @Test
    void theWatchdogHoldsASilentMovingProgramUntilItSpeaks() throws IOException {
        long[] now = { 0 };
        Reports reports = new Reports();
        RobotHold holds = new RobotHold(reports, () -> now[0]);
        holds.setEnabled(true);
        ByteArrayOutputStream player = new ByteArrayOutputStream();
        HoldingForwarder f = holds.attach(CONN, player);
        Msg cmd = MESSAGES.stream().filter(Msg::motion).findFirst().orElseThrow();
        f.relay(PROGRAM, 0, cmd.end()); // last command: 0.4 m/s
        assertTrue(f.moving());
        holds.setWatchdog(java.time.Duration.ofHours(1)); // its thread will not fire during the test
        now[0] += 3_599_000_000_000L;
        holds.watchdogCheck(now[0]);
        assertFalse(holds.isHeld(), "not silent for the whole timeout yet");
        now[0] += 1_000_000_000L;
        holds.watchdogCheck(now[0]);
        assertTrue(holds.isHeld());
        assertEquals(Map.of(HoldReason.WATCHDOG, 1), holds.reasons());
        assertEquals(cmd.end() + 68, player.size(), "zero command sent");
        holds.watchdogCheck(now[0] + 1);
        assertEquals(Map.of(HoldReason.WATCHDOG, 1), holds.reasons(), "one hold per silence");
        Msg next = MESSAGES.stream().filter(m -> m.offset() >= cmd.end()).findFirst().orElseThrow();
        f.relay(PROGRAM, next.offset(), next.length());
        assertFalse(holds.isHeld(), "it spoke: released");
        holds.close();
    }

    @Test
    void theWatchdogLeavesAStoppedRobotAlone() throws IOException {
        long[] now = { 0 };
        RobotHold holds = new RobotHold(HoldObserver.NONE, () -> now[0]);
        holds.setEnabled(true);
        HoldingForwarder f = holds.attach(CONN, new ByteArrayOutputStream());
        byte[] stop = ZeroVelocity.command(MESSAGES.stream().filter(Msg::motion).findFirst().orElseThrow().header(), 1);
        f.relay(stop, 0, stop.length);
        assertFalse(f.moving());
        holds.setWatchdog(java.time.Duration.ofHours(1));
        now[0] += 7_200_000_000_000L;
        holds.watchdogCheck(now[0]);
        assertFalse(holds.isHeld());
        holds.close();
    }

    @Test
    void reasonsAreCountedAndListenersSeeEveryChangeInOrder() {
        RobotHold holds = new RobotHold(HoldObserver.NONE);
        List<HoldState> seen = new ArrayList<>();
        holds.addListener(seen::add);
        holds.hold(HoldReason.SUSPENDED);
        assertFalse(holds.isHeld(), "holds are off until enabled");
        assertTrue(holds.description().startsWith("Robot holds off"));
        assertNull(holds.attach(CONN, new ByteArrayOutputStream()), "off: the relay stays the byte copy");
        holds.setEnabled(true);
        assertTrue(holds.isHeld(), "a reason held before enabling holds once enabled");
        holds.hold(HoldReason.SUSPENDED);
        holds.hold(HoldReason.EMERGENCY_STOP);
        assertTrue(holds.release(HoldReason.SUSPENDED));
        assertTrue(holds.isHeld());
        assertTrue(holds.release(HoldReason.SUSPENDED));
        assertFalse(holds.release(HoldReason.SUSPENDED), "not held any more");
        assertTrue(holds.isHeld(), "the emergency stop still holds");
        assertTrue(holds.description().contains("emergency stop"), holds.description());
        holds.releaseAll(HoldReason.EMERGENCY_STOP);
        assertFalse(holds.isHeld());
        List<Boolean> held = seen.stream().map(HoldState::held).toList();
        assertEquals(List.of(false, true, true, true, true, true, false), held);
        assertEquals(Map.of(HoldReason.SUSPENDED, 2, HoldReason.EMERGENCY_STOP, 1), seen.get(3).reasons());
        assertEquals(Map.of(HoldReason.SUSPENDED, 1, HoldReason.EMERGENCY_STOP, 1), seen.get(4).reasons());
        assertEquals(1, seen.get(1).epoch());
    }
}
