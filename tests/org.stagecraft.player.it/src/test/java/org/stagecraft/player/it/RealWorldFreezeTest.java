package org.stagecraft.player.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.SupervisedTool;
import org.stagecraft.tools.process.ToolListener;
import org.stagecraft.tools.process.ToolSpec;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.session.SessionConfig;
import org.stagecraft.tools.session.SpyOptions;
import org.stagecraft.tools.world.WorldFreeze;
import org.stagecraft.tools.world.WorldState;

/**
 * The frozen world on a real Player 3.1.1-dev with Stage 4.3.0 (docs/debugging-robots.md): a Robot Session on
 * two-robots.cfg, "r0" driven through the spy by a program, "r1" by Stage's own pioneer_flocking controller,
 * which no hold reaches. The session holds its robots as the debugger's suspend does ({@link HoldReason#SUSPENDED});
 * for 5 s the simulated time may advance by at most one update (100 ms) and no model may move by more than 1 mm;
 * after the release both robots move and time runs. With the option off, r1 drives on while r0 is held. Stage runs
 * with its window (on a private Xvfb, the IDE's case) and without (the headless cfg): Stage stops differently.
 */
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RealWorldFreezeTest {
    private static final Duration WAIT = Duration.ofSeconds(60);
    private static final long SUSPENDED_MS = 5_000;
    private static final double ONE_UPDATE_S = 0.100; // interval_sim of two-robots.world

    @TempDir
    Path tmp;

    private final SessionConsole listener = new SessionConsole();
    private final List<PlayerStage.Program> programs = new ArrayList<>();
    private RobotSession session;
    /** The X display of the session's own Xvfb, for a session with Stage's window. */
    private int display;


    @AfterEach
    void stopEverything() throws Exception {
        for (PlayerStage.Program p : programs) {
            p.close();
        }
        if (session != null) {
            session.close();
        }
    }

    private SessionConfig config(boolean window, boolean freeze) throws Exception {
        int port = PlayerStage.freePorts(1).get(0);
        Map<String, String> env = new HashMap<>(PlayerStage.env());
        List<ToolSpec> tools = List.of();
        if (window) {
            int display = PlayerStage.freeDisplay();
            this.display = display;
            tools = List.of(PlayerStage.xvfb(display));
            env.put("DISPLAY", ":" + display);
        }
        Path cfg = PlayerStage.worlds().resolve(window ? "two-robots.cfg" : "two-robots-headless.cfg");
        return SessionConfig.of(cfg).withPlayer(List.of(PlayerStage.player().toString()), env).withDefaultPort(port)
                .withPlayerRestart(RestartPolicy.NEVER, Duration.ofSeconds(30)).withTools(tools)
                .withLog(tmp.resolve("spy-logs/session.mcap")).withScratchRoot(tmp.resolve("scratch"))
                .withSpyOptions(SpyOptions.DEFAULT.withFreezeWorld(freeze));
    }

    /** Starts the session and r0's program (driving in a slow circle through the spy), and waits until both robots move. */
    private StageSimulation startMoving(SessionConfig c) throws Exception {
        session = RobotSession.start(c, listener);
        Map<String, String> env = new HashMap<>();
        env.put("PYTHONPATH", PlayerStage.pythonClient().resolve("src").toString());
        PlayerStage.Program drive = new PlayerStage.Program("drive.py", List.of(PlayerStage.python(), "-u",
                PlayerStage.script("drive.py").toString(), "--port", String.valueOf(c.defaultPort()), "--speed", "0.2", "--turn",
                "0.2", "--rounds", "1000000"), env, null);
        programs.add(drive);
        StageSimulation sim = new StageSimulation(session.portMap().get(c.defaultPort()));
        StageSimulation.Pose r0 = sim.pose("r0");
        StageSimulation.Pose r1 = sim.pose("r1");
        assertTrue(PlayerStage.await(WAIT, () -> moved(sim, "r0", r0) && moved(sim, "r1", r1)),
                "both robots move before the hold:\n" + drive.output() + "\n" + listener);
        return sim;
    }

    private static boolean moved(StageSimulation sim, String model, StageSimulation.Pose from) {
        try {
            return sim.pose(model).distanceTo(from) > 0.05;
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void withItsWindowTheWorldStandsStillWhileTheRobotsAreHeld() throws Exception {
        theWorldStandsStillWhileHeldAndRunsOnAfter(true);
    }

    @Test
    void withoutAWindowTheWorldStandsStillWhileTheRobotsAreHeld() throws Exception {
        theWorldStandsStillWhileHeldAndRunsOnAfter(false);
    }

    private void theWorldStandsStillWhileHeldAndRunsOnAfter(boolean window) throws Exception {
        StageSimulation sim = startMoving(config(window, true));
        WorldFreeze world = session.world();
        assertTrue(world != null, "the session freezes its world: " + session.worldProblem() + "\n" + listener);
        LinkedBlockingQueue<WorldState> changes = new LinkedBlockingQueue<>();
        world.addListener((s, problem) -> changes.add(s));

        // freeze latency, hold to frozen (the world driver's answer), over 20 holds
        double[] freezeMs = new double[20];
        for (int i = 0; i < freezeMs.length; i++) {
            long t0 = System.nanoTime();
            session.holds().hold(HoldReason.SUSPENDED);
            WorldState frozen = changes.poll(10, TimeUnit.SECONDS);
            freezeMs[i] = (System.nanoTime() - t0) / 1e6;
            assertTrue(frozen != null && frozen.frozen(), "frozen after hold " + i + ": " + frozen);
            session.holds().release(HoldReason.SUSPENDED);
            WorldState thawed = changes.poll(10, TimeUnit.SECONDS);
            assertTrue(thawed != null && !thawed.frozen(), "thawed after release " + i + ": " + thawed);
        }
        Arrays.sort(freezeMs);
        System.out.printf(Locale.ROOT, "world freeze (%s): hold -> frozen p50 %.1f ms, p99 %.1f ms, max %.1f ms (20 holds)%n",
                window ? "Stage with its window" : "Stage without a window", freezeMs[9], freezeMs[19], freezeMs[19]);

        session.holds().hold(HoldReason.SUSPENDED);
        WorldState frozen = changes.poll(10, TimeUnit.SECONDS);
        assertTrue(frozen != null && frozen.frozen(), "frozen: " + frozen);
        StageSimulation.Pose r0 = sim.pose("r0");
        StageSimulation.Pose r1 = sim.pose("r1");
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(SUSPENDED_MS);
        double maxMove = 0;
        StageSimulation.Pose r0Now = r0;
        StageSimulation.Pose r1Now = r1;
        while (System.nanoTime() < end) { // watch the world for the whole suspension, not only at its ends
            r0Now = sim.pose("r0");
            r1Now = sim.pose("r1");
            maxMove = Math.max(maxMove, Math.max(r0Now.distanceTo(r0), r1Now.distanceTo(r1)));
            Thread.sleep(100);
        }
        double timeAdvanced = r1Now.simTime() - r0.simTime();
        System.out.printf(Locale.ROOT, "frozen %d ms: simulated time advanced %.3f s, largest model move %.4f mm%n", SUSPENDED_MS,
                timeAdvanced, maxMove * 1000);
        assertTrue(timeAdvanced <= ONE_UPDATE_S + 1e-9, "simulated time advanced by " + timeAdvanced + " s while frozen");
        assertTrue(maxMove <= 0.001, "a model moved " + maxMove + " m while frozen (r0 " + r0 + " -> " + r0Now + ", r1 " + r1 + " -> "
                + r1Now + ")");

        session.holds().release(HoldReason.SUSPENDED);
        WorldState thawed = changes.poll(10, TimeUnit.SECONDS);
        assertTrue(thawed != null && !thawed.frozen(), "thawed: " + thawed);
        StageSimulation.Pose r0After = sim.pose("r0");
        StageSimulation.Pose r1After = sim.pose("r1");
        assertTrue(PlayerStage.await(WAIT, () -> moved(sim, "r0", r0After) && moved(sim, "r1", r1After)),
                "both robots move again after the release");
        assertTrue(sim.pose("r1").simTime() > r1After.simTime(), "simulated time runs again");
        session.close();

        try (SpyLogReader r = SpyLogReader.open(tmp.resolve("spy-logs/session.mcap"))) {
            List<HoldEntry> holds = r.holdEntries();
            long freezes = holds.stream().filter(e -> e.action() == HoldEntry.Action.WORLD_FROZEN).count();
            long thaws = holds.stream().filter(e -> e.action() == HoldEntry.Action.WORLD_THAWED).count();
            assertEquals(21, freezes, "every freeze is in the spy log");
            assertEquals(21, thaws, "every thaw is in the spy log");
            HoldEntry lastFreeze = holds.stream().filter(e -> e.action() == HoldEntry.Action.WORLD_FROZEN).reduce((a, b) -> b).get();
            assertTrue(lastFreeze.text().contains("suspended in the debugger"), lastFreeze.text());
            HoldEntry on = holds.stream().filter(e -> e.action() == HoldEntry.Action.HOLD_ON).reduce((a, b) -> b).get();
            assertTrue(on.timeNanos() <= lastFreeze.timeNanos(), "the robots are held before the world freezes");
        }
    }

    /**
     * Issue 24, item 6: Stage's window, covered by another window (as the workbench covers it on the first
     * click), comes to the front when asked (Show Stage's Window): the window stacking order, read from the X
     * server with xwininfo, before and after.
     */
    @Test
    void stagesWindowComesToTheFrontWhenAsked() throws Exception {
        SessionConfig c = config(true, true);
        session = RobotSession.start(c, listener);
        WorldFreeze world = session.world();
        assertTrue(world != null, session.worldProblem() + "\n" + listener);
        assertTrue(PlayerStage.await(WAIT, () -> stacking().stream().anyMatch(RealWorldFreezeTest::isStage)),
                "Stage's window on the display: " + stacking());
        Process cover = new ProcessBuilder("xmessage", "-display", ":" + display, "-name", "cover", "-geometry", "1200x1000+0+0",
                "a window over Stage's").redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        try {
            assertTrue(PlayerStage.await(WAIT, () -> above("cover", stacking())), "the cover over Stage's window: " + stacking());
            WorldState s = world.raiseWindow().get(10, TimeUnit.SECONDS);
            assertTrue(s.gui(), "Stage runs with its window: " + s);
            assertTrue(PlayerStage.await(Duration.ofSeconds(10), () -> !above("cover", stacking())),
                    "Stage's window in front of the cover: " + stacking());
        } finally {
            cover.destroyForcibly();
        }
    }

    /** Stage's window: FLTK's class, its world file in the title. */
    private static boolean isStage(String line) {
        return line.contains("(\"FLTK\" \"FLTK\")") && line.contains(".world");
    }

    /** Whether the window named {@code name} is above Stage's (xwininfo lists the topmost first). */
    private static boolean above(String name, List<String> stacking) {
        for (String line : stacking) {
            if (line.contains("\"" + name + "\"")) {
                return true;
            }
            if (isStage(line)) {
                return false;
            }
        }
        return false;
    }

    /** The root window's children, topmost first, as xwininfo prints them. */
    private List<String> stacking() {
        try {
            Process p = new ProcessBuilder("xwininfo", "-display", ":" + display, "-root", "-children").redirectErrorStream(true)
                    .start();
            String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            p.waitFor();
            return out.lines().filter(l -> l.trim().startsWith("0x")).toList();
        } catch (java.io.IOException e) {
            throw new AssertionError("xwininfo (x11-utils) is needed for this test: " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }

    /** Player killed and restarted by its restart policy: the next hold still freezes the world (of the new Player). */
    @Test
    void afterPlayerIsRestartedTheWorldStillFreezes() throws Exception {
        SessionConfig c = config(false, true).withPlayerRestart(RestartPolicy.onFailure(1), Duration.ofSeconds(30));
        session = RobotSession.start(c, listener);
        WorldFreeze world = session.world();
        assertTrue(world != null, session.worldProblem());
        LinkedBlockingQueue<WorldState> changes = new LinkedBlockingQueue<>();
        world.addListener((s, problem) -> changes.add(s));
        ProcessHandle first = session.player().process();
        first.destroyForcibly();
        assertTrue(PlayerStage.await(WAIT, () -> session.player().process() != null && session.player().process().pid() != first.pid()
                && session.player().state() == ToolState.READY), "Player was restarted:\n" + listener);
        session.holds().hold(HoldReason.SUSPENDED);
        WorldState frozen = changes.poll(20, TimeUnit.SECONDS);
        assertTrue(frozen != null && frozen.frozen(), "the new Player's world froze: " + frozen + "\n" + listener);
        try (StageSimulation sim = new StageSimulation(session.portMap().get(c.defaultPort()))) {
            StageSimulation.Pose a = sim.pose("r1");
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(1);
            StageSimulation.Pose b = a;
            while (System.nanoTime() < end) {
                b = sim.pose("r1");
            }
            assertTrue(b.simTime() - a.simTime() <= ONE_UPDATE_S + 1e-9 && b.distanceTo(a) <= 0.001,
                    "the new world stands still: " + a + " -> " + b);
        }
        session.holds().release(HoldReason.SUSPENDED);
        WorldState thawed = changes.poll(20, TimeUnit.SECONDS);
        assertTrue(thawed != null && !thawed.frozen(), "thawed: " + thawed);
    }

    @Test
    void withTheOptionOffTheOtherRobotDrivesOnWhileTheProgramsRobotIsHeld() throws Exception {
        StageSimulation sim = startMoving(config(false, false));
        assertEquals(null, session.world(), "no world driver when the option is off");
        session.holds().hold(HoldReason.SUSPENDED);
        StageSimulation.Pose r0 = sim.pose("r0");
        StageSimulation.Pose r1 = sim.pose("r1");
        Thread.sleep(SUSPENDED_MS); // the length of the suspension under test, as above
        StageSimulation.Pose r0Now = sim.pose("r0");
        StageSimulation.Pose r1Now = sim.pose("r1");
        System.out.printf(Locale.ROOT, "option off, held %d ms: simulated time advanced %.3f s, r0 moved %.4f m, r1 moved %.3f m%n",
                SUSPENDED_MS, r1Now.simTime() - r0.simTime(), r0Now.distanceTo(r0), r1Now.distanceTo(r1));
        assertTrue(r1Now.simTime() - r0.simTime() > 1.0, "simulated time runs on");
        assertTrue(r1Now.distanceTo(r1) > 0.1, "r1, driven by its Stage controller, drives on: " + r1 + " -> " + r1Now);
        assertTrue(r0Now.distanceTo(r0) < 0.05, "r0, its program held, stands: " + r0 + " -> " + r0Now);
        session.holds().release(HoldReason.SUSPENDED);
    }
}
