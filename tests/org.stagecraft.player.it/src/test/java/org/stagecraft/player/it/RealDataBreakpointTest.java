package org.stagecraft.player.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * Robot data breakpoints without the IDE, on a real Player 3.1.1-dev with Stage 4.3.0: {@code ./stagecraft
 * spy --break 'laser:0 min(ranges) < 0.8'} in front of Player, a program driving the Pioneer straight at a
 * wall at 0.4 m/s while it reads the laser. The spy must hold the robots at the first scan nearer than
 * 0.8 m — found here independently in the spy log's record of what Player sent — keep every motion
 * command of the program from Player until Enter releases, and the program must have read that scan.
 */
@Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RealDataBreakpointTest {
    private static final Duration WAIT = Duration.ofSeconds(60);

    @TempDir
    Path tmp;

    private final List<PlayerStage.Program> programs = new ArrayList<>();

    @AfterEach
    void stopEverything() throws Exception {
        for (PlayerStage.Program p : programs) {
            p.close();
        }
    }

    private PlayerStage.Program start(String name, List<String> command, Map<String, String> env, Path dir) throws Exception {
        PlayerStage.Program p = new PlayerStage.Program(name, command, env, dir);
        programs.add(p);
        return p;
    }

    /** The first laser scan in Player's stream whose nearest return is nearer than {@code metres}: [offset, timestamp bits]. */
    private static long[] firstScanNearerThan(byte[] s2c, float metres) {
        PlayerDecoder d = new PlayerDecoder(CodecRegistry.standard());
        List<long[]> found = new ArrayList<>();
        new PlayerFramer(Direction.SERVER_TO_CLIENT, e -> {
            if (found.isEmpty() && e instanceof WireEvent.Frame f && f.header().type() == 1
                    && d.decode(f.header(), f.payload()).body() instanceof Laser.Scan s) {
                for (float r : s.ranges().toArray()) {
                    if (r < metres) {
                        found.add(new long[] { f.offset(), Double.doubleToLongBits(f.header().timestamp()) });
                        return;
                    }
                }
            }
        }).accept(s2c);
        assertTrue(!found.isEmpty(), "Player sent no scan nearer than " + metres + " m");
        return found.get(0);
    }

    @Test
    void theSpyHoldsTheRobotAtTheFirstScanNearerThanTheCondition() throws Exception {
        List<Integer> ports = PlayerStage.freePorts(2);
        int playerPort = ports.get(0);
        int spyPort = ports.get(1);
        start("player", List.of(PlayerStage.player().toString(), "-p", String.valueOf(playerPort), "pioneer-laser-sonar-headless.cfg"),
                PlayerStage.env(), PlayerStage.worlds());
        assertTrue(PlayerStage.await(WAIT, () -> !PlayerStage.isFree(playerPort)), "Player listens on " + playerPort);

        Path log = tmp.resolve("break.mcap");
        PlayerStage.Program spy = start("stagecraft spy", List.of(PlayerStage.root().resolve("stagecraft").toString(), "spy",
                "--listen", String.valueOf(spyPort), "--to", "127.0.0.1:" + playerPort, "--log", log.toString(),
                "--break", "laser:0 min(ranges) < 0.8"), Map.of(), PlayerStage.root());
        assertTrue(PlayerStage.await(WAIT, () -> spy.anyLine(l -> l.startsWith("spying "))), "the spy started:\n" + spy.output());

        Map<String, String> env = new HashMap<>();
        env.put("PYTHONPATH", PlayerStage.pythonClient().resolve("src").toString());
        // the program never stops by itself: headless Stage runs ahead of the program's reads, so the data Player has
        // queued can show the robot nearer than it is once held; whether it stood still is read from the log below
        PlayerStage.Program wall = start("to_the_wall.py", List.of(PlayerStage.python(), "-u", PlayerStage.script("to_the_wall.py").toString(),
                "--port", String.valueOf(spyPort), "--speed", "0.4", "--stop", "0", "--rounds", "1000000"), env, null);
        assertTrue(PlayerStage.await(WAIT, () -> spy.anyLine(l -> l.contains("BREAK robot data breakpoint"))),
                "the breakpoint held:\n" + spy.output() + "\nthe program:\n" + wall.output());
        String hitLine = spy.lines.stream().filter(l -> l.contains("BREAK robot data breakpoint")).findFirst().orElseThrow();
        Matcher m = Pattern.compile("connection 1 at byte (\\d+) .*time ([0-9.]+)\\)").matcher(hitLine);
        assertTrue(m.find(), hitLine);
        long hitOffset = Long.parseLong(m.group(1));
        // held, the program reads on (its commands are kept from Player)
        long readBefore = wall.count(l -> l.startsWith("scan "));
        assertTrue(PlayerStage.await(WAIT, () -> wall.count(l -> l.startsWith("scan ")) >= readBefore + 60),
                "the program reads on while its robot is held:\n" + wall.output() + "\nthe spy:\n" + spy.output());

        // Enter releases; on the command line a breakpoint stops again only once its condition has stopped holding,
        // so the robot drives on towards the wall
        OutputStream keys = spy.process.getOutputStream();
        keys.write('\n');
        keys.flush();
        assertTrue(PlayerStage.await(WAIT, () -> spy.anyLine(l -> l.contains("released: the robots move again"))), spy.output());
        long readAtRelease = wall.count(l -> l.startsWith("scan "));
        assertTrue(PlayerStage.await(WAIT, () -> wall.count(l -> l.startsWith("scan ")) >= readAtRelease + 40), wall.output());
        assertEquals(1, spy.count(l -> l.contains("BREAK robot data breakpoint")), "no second stop while still near:\n" + spy.output());
        wall.close();
        spy.process.destroy(); // SIGTERM: the spy closes its log and exits
        assertEquals(0, spy.awaitExit(WAIT), spy.output());

        try (SpyLogReader r = SpyLogReader.open(log)) {
            byte[] s2c = r.streamBytes(1, Direction.SERVER_TO_CLIENT);
            long[] first = firstScanNearerThan(s2c, 0.8f);
            assertEquals(first[0], hitOffset, "held at the first scan nearer than 0.8 m");
            double stamp = Double.longBitsToDouble(first[1]);
            assertTrue(wall.anyLine(l -> l.startsWith("scan ") && Double.parseDouble(l.split(" ")[2]) == stamp),
                    "the program read the triggering scan (time " + stamp + "):\n" + wall.output());

            List<HoldEntry> holds = r.holdEntries();
            HoldEntry brk = holds.stream().filter(e -> e.action() == HoldEntry.Action.BREAK).findFirst().orElseThrow();
            assertEquals(hitOffset, brk.programOffset());
            HoldEntry off = holds.stream().filter(e -> e.action() == HoldEntry.Action.HOLD_OFF && e.timeNanos() > brk.timeNanos())
                    .findFirst().orElseThrow();
            assertTrue(holds.stream().anyMatch(e -> e.action() == HoldEntry.Action.INJECTED && e.timeNanos() >= brk.timeNanos()),
                    "zero velocity was sent to Player at the hit");
            // every motion command the program sent between the hit and the release was kept from Player
            java.util.Set<Long> heldBack = new java.util.HashSet<>();
            holds.stream().filter(e -> e.action() == HoldEntry.Action.HELD_BACK).forEach(e -> heldBack.add(e.programOffset()));
            List<Long> sentWhileHeld = new ArrayList<>();
            for (var it = r.entries(); it.hasNext();) {
                if (it.next() instanceof LogEntry.Wire w && w.conn() == 1 && w.dir() == Direction.CLIENT_TO_SERVER
                        && w.kind() == LogEntry.Kind.FRAME && w.timeNanos() >= brk.timeNanos() && w.timeNanos() < off.timeNanos()) {
                    MessageHeader h = MessageHeader.read(w.bytes(), 0);
                    if (h.interf() == Position2d.CODE && h.type() == 2) {
                        sentWhileHeld.add(w.streamOffset());
                    }
                }
            }
            assertTrue(sentWhileHeld.size() >= 5, "the program kept commanding its robot while held: " + sentWhileHeld.size());
            for (long o : sentWhileHeld) {
                assertTrue(heldBack.contains(o), "the motion command at byte " + o + " of the program's stream reached Player");
            }
            // the robot stood while held: the last poses Player reported before the release agree within 1 mm, and
            // after the release it moved
            List<double[]> held = new ArrayList<>();
            List<double[]> after = new ArrayList<>();
            PlayerDecoder d = new PlayerDecoder(CodecRegistry.standard());
            for (var it = r.entries(); it.hasNext();) {
                if (it.next() instanceof LogEntry.Wire w && w.conn() == 1 && w.dir() == Direction.SERVER_TO_CLIENT
                        && w.kind() == LogEntry.Kind.FRAME && w.timeNanos() > brk.timeNanos()) {
                    MessageHeader h = MessageHeader.read(w.bytes(), 0);
                    if (d.decode(h, java.util.Arrays.copyOfRange(w.bytes(), MessageHeader.SIZE, w.bytes().length)).body()
                            instanceof Position2d.State st) {
                        (w.timeNanos() < off.timeNanos() ? held : after).add(new double[] { st.pos().px(), st.pos().py() });
                    }
                }
            }
            assertTrue(held.size() >= 20, "poses while held: " + held.size());
            double[] still = held.get(held.size() - 1);
            double spread = held.subList(held.size() - 10, held.size()).stream()
                    .mapToDouble(p -> Math.hypot(p[0] - still[0], p[1] - still[1])).max().orElseThrow();
            assertTrue(spread <= 0.001, "the held robot stood still: the last 10 poses before the release within " + spread + " m");
            double moved = after.stream().mapToDouble(p -> Math.hypot(p[0] - still[0], p[1] - still[1])).max().orElse(0);
            assertTrue(moved > 0.005, "released, the robot drove on: " + moved + " m");
            System.out.println("RealDataBreakpointTest: held at byte " + hitOffset + " (scan time " + stamp + "), "
                    + sentWhileHeld.size() + " motion commands held back until Enter; the last 10 poses while held within " + spread
                    + " m; " + moved + " m driven after the releases");
        }
    }

}
