package org.stagecraft.pydev.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.core.model.IThread;
import org.eclipse.jface.text.IDocument;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.texteditor.ITextEditor;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.Timeout;
import org.python.pydev.debug.model.PyBreakpoint;
import org.python.pydev.debug.ui.actions.PyBreakpointRulerAction;
import org.stagecraft.spy.hold.HoldListener;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;
import org.stagecraft.tools.world.WorldFreeze;
import org.stagecraft.tools.ui.launch.EmergencyStop;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionHolds;
import org.stagecraft.tools.ui.launch.SessionParts;

/**
 * The debugger-safe robot against the real things (issue 19's "must show"): a Robot Session with the
 * real PyDev (its debugger pydevd) and a real Player 3.1.1-dev + Stage 4.3.0, Stage with its window on
 * a private Xvfb display so that it runs in real time ({@code speedup 1}). A robot program drives the
 * Pioneer forward at 0.3 m/s; the test reads the robot's pose from Stage itself, through the
 * {@code simulation} interface's GET_POSE2D request on a second connection straight to Player (not
 * through the spy, and not by subscribing to position2d, which would zero the robot's speed when that
 * client leaves; a suspended program reads nothing, so the spy log has no poses while suspended).
 *
 * <p>Runs only in the combined tier: with PyDev (the pydev-tier profile) and -Dstagecraft.playerStage
 * naming a Player/Stage install (the module's real-stage profile includes this class then); and
 * -Dstagecraft.python, a python3 with pint for the stagecraft_player client, which PyDev is configured with.
 *
 * <p>Times: the poses are stamped by the pose reader with {@code time.monotonic_ns()} (CLOCK_MONOTONIC,
 * the clock of Java's {@code System.nanoTime()} on Linux), so they compare with the arrival of the
 * debug events here. Figures go to the test output and to {@code target/hold-latency.txt}.
 */
// PyDev logs its first analysis of a new project as an ERROR ("Info: Rebuilding internal caches"): PyDev's, not ours
@LogsErrors({ "^org\\.python\\.pydev\\.shared_core: Info: Rebuilding internal caches" })
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class RealStageHoldTest {
    private static final Duration WAIT = Duration.ofSeconds(60);
    private static final double SPEED = 0.3;
    private static final long MS = 1_000_000L;
    private static final String BREAK_MARK = "# the breakpoint's line";
    /** The robot program: drives forward; every MARK_EVERY seconds of driving (MARKS times) it passes the marked line. */
    private static final String ROBOT = """
            import os, time
            from stagecraft_player import Client

            every = float(os.environ["MARK_EVERY"])
            marks = int(os.environ["MARKS"])
            silence = float(os.environ.get("SILENCE", "0"))
            with Client("127.0.0.1", int(os.environ["ROBOT_PORT"])) as client:
                robot = client.position2d("position2d:0")
                robot.enable_motors(True)
                last = time.monotonic()
                done = 0
                while True:
                    client.read()
                    robot.set_speed(%s, 0.0)
                    if done < marks and time.monotonic() - last > every:
                        done += 1  %s
                        # renamed into place: the test reads the mark as soon as it exists
                        with open(os.environ["MARK"] + ".tmp", "w") as f:
                            f.write("%%d\\n" %% time.monotonic_ns())
                        os.rename(os.environ["MARK"] + ".tmp", os.environ["MARK"] + str(done))
                        if silence > 0:
                            time.sleep(silence)  # silent: no command, no read
                        last = time.monotonic()
            """.formatted(SPEED, BREAK_MARK);
    /** Reads r0's pose from Stage through Player's simulation interface, stamped with CLOCK_MONOTONIC. */
    private static final String POSES = """
            import sys, time
            from stagecraft_player import Client
            with Client("127.0.0.1", int(sys.argv[1])) as c:
                sim = c.simulation(0)
                print("READY", flush=True)
                while True:
                    p = sim.get_pose2d("r0")
                    print("POSE %d %.5f %.5f %.5f" % (time.monotonic_ns(), p.px, p.py, p.pa), flush=True)
                    time.sleep(0.01)  # sampling period (~20 Hz with Player's own turnaround); not a synchronisation
            """;

    /** Both robots' poses and Stage's simulated time in seconds (GET_POSE3D answers it, in microseconds), stamped with CLOCK_MONOTONIC. */
    private static final String WORLD_POSES = """
            import sys, time
            from stagecraft_player import Client
            with Client("127.0.0.1", int(sys.argv[1])) as c:
                sim = c.simulation(0)
                while True:
                    p0, t0 = sim.get_pose3d("r0")
                    p1, t1 = sim.get_pose3d("r1")
                    print("WORLD %d %r %.6f %.6f %.6f %.6f" % (time.monotonic_ns(), t1 / 1e6, p0.px, p0.py, p1.px, p1.py), flush=True)
                    time.sleep(0.05)  # sampling period; not a synchronisation
            """;

    /** The data breakpoint's program: drives straight on at 0.4 m/s, writing down each laser scan it reads. */
    private static final String TO_THE_WALL = """
            import os
            from stagecraft_player import Client
            scans = open(os.environ["SCANS"], "a")
            with Client("127.0.0.1", int(os.environ["ROBOT_PORT"])) as client:
                robot = client.position2d("position2d:0")
                laser = client.laser("laser:0")
                robot.enable_motors(True)
                while True:
                    for m in client.read():
                        if m.header.interf == 6 and m.header.type == 1 and hasattr(m.record, "ranges"):
                            scans.write("scan %r %r\\n" % (m.header.timestamp, min(m.record.ranges)))
                            scans.flush()
                    robot.set_speed(0.4, 0.0)
            """;
    /** Puts r0 at a pose through Player's simulation interface (SET_POSE2D), then exits. */
    private static final String TELEPORT = """
            import sys
            from stagecraft_player import Client
            with Client("127.0.0.1", int(sys.argv[1])) as c:
                c.simulation(0).set_pose2d("r0", float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]))
            print("MOVED", flush=True)
            """;

    private static final List<String> REPORT = new CopyOnWriteArrayList<>();
    private static String python;
    private static Map<String, String> playerEnv;

    private final List<ILaunch> launches = new ArrayList<>();
    private final List<Proc> procs = new ArrayList<>();
    private Path tmp;
    private IProject project;
    private int display;

    // ------------------------------------------------------------------------------------------ set-up

    @BeforeAll
    static void pyDevWithThePythonOfTheClientAndPlayerStage() throws Exception {
        python = System.getProperty("stagecraft.python", "");
        if (python.isBlank() || python.startsWith("${")) {
            fail("-Dstagecraft.python (a python3 with pint, for the stagecraft_player client) is not set");
        }
        Process check = new ProcessBuilder(python, "-c", "import pint").redirectErrorStream(true).start();
        String out = new String(check.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(check.waitFor(60, TimeUnit.SECONDS) && check.exitValue() == 0, python + " has no pint: " + out);
        PyDevInterpreter.configure(python);
        playerEnv = playerStageEnv();
    }

    @AfterAll
    static void writeFigures() throws IOException {
        String file = System.getProperty("stagecraft.holdReport");
        Path out = file == null || file.isBlank() || file.startsWith("${") ? Path.of("hold-latency.txt") : Path.of(file);
        Files.createDirectories(out.toAbsolutePath().getParent());
        Files.writeString(out, "# RealStageHoldTest: robot holds with real PyDev + Player/Stage (Stage in real time), "
                + java.time.Instant.now() + "\n" + String.join("\n", REPORT) + "\n",
                StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING);
        System.out.println("RealStageHoldTest figures written to " + out.toAbsolutePath());
    }

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-realhold");
        project = pyDevProjectWithWorlds("realhold-" + System.nanoTime());
        display = freeDisplay();
        Proc xvfb = start("Xvfb", List.of("Xvfb", ":" + display, "-screen", "0", "640x480x24", "-nolisten", "tcp", "-displayfd", "1"),
                Map.of());
        Await.until("Xvfb :" + display + " to be ready", WAIT, () -> xvfb.lines.contains(String.valueOf(display)), xvfb::output);
    }

    @AfterEach
    void tearDown() throws Exception {
        EmergencyStop.get().release();
        List<ProcessHandle> players = new ArrayList<>();
        List<Integer> ports = new ArrayList<>();
        for (ILaunch l : launches) {
            SessionParts parts = RobotSessionLaunchDelegate.partsOf(l);
            if (parts != null) {
                players.add(parts.session().player().process());
                ports.addAll(parts.session().portMap().keySet());
                ports.addAll(parts.session().portMap().values());
            }
            if (!l.isTerminated()) {
                l.terminate();
            }
        }
        for (ILaunch l : launches) {
            Await.until("the session to end", WAIT, l::isTerminated, () -> "");
            DebugPlugin.getDefault().getLaunchManager().removeLaunch(l);
        }
        for (int i = procs.size() - 1; i >= 0; i--) {
            procs.get(i).close();
        }
        for (ProcessHandle h : players) {
            Await.until("Player " + h.pid() + " to be gone", WAIT, () -> !h.isAlive(), () -> "");
        }
        for (int port : ports) {
            Await.until("port " + port + " to be free again", WAIT, () -> isFree(port), () -> "");
        }
        DebugPlugin.getDefault().getBreakpointManager().removeBreakpoints(
                DebugPlugin.getDefault().getBreakpointManager().getBreakpoints(), true);
        Display.getDefault().syncExec(() -> {
            var page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
            page.closeAllEditors(false);
        });
        project.delete(true, true, new NullProgressMonitor());
    }

    // ------------------------------------------------------------------------------------------ the tests

    @Test
    @Order(1) // first: its pictures then show no robot left in the live Robot View by an earlier test's session
    void atABreakpointTheHeldRobotStopsWithin200msStaysStillAndDrivesOnAfterResume() throws Exception {
        List<Suspension> runs = suspendAtBreakpoint(true, 3);
        for (Suspension s : runs) {
            assertTrue(s.speedBefore > 0.2, "the robot drove before the breakpoint: " + s);
            assertTrue(s.toStill < 0.06, "the robot stopped within 200 ms of the SUSPEND event, less than 6 cm further: " + s);
            assertTrue(s.drift < 0.01, "the held robot stayed within 1 cm for 3 s: " + s);
            assertTrue(s.holdingWhileSuspended, "SuspendHold held the robots while suspended: " + s);
            assertTrue(s.resumeMovedMs >= 0, "the robot moved again after resume: " + s);
            assertTrue(s.injectedMs >= 0 && s.injectedMs < 200, "the zero CMD_VEL went to Player within 200 ms of the SUSPEND event: " + s);
        }
    }

    /**
     * Issue 27, the frozen world: two-robots.cfg, r0 driven by the program under PyDev's debugger, r1 by Stage's own
     * pioneer_flocking controller. Suspended 5 s at a real breakpoint: with the option on, simulated time advances by
     * at most one Stage update (100 ms) and no model moves by more than 1 mm, and after Resume both robots move and
     * time runs; with it off, r1 drives on and time runs while r0 is held.
     */
    @Test
    void atABreakpointTheWholeSimulatedWorldStandsStillAndRunsOnAfterResume() throws Exception {
        double[] on = suspendedFiveSecondsInTheTwoRobotWorld(true);
        report(String.format(java.util.Locale.ROOT, "frozen world on, suspended 5 s at a PyDev breakpoint: simulated time +%.3f s, "
                + "largest model move %.4f mm, hold -> world frozen %.1f ms", on[0], on[1] * 1000, on[2]));
        assertTrue(on[0] <= 0.100 + 1e-9, "simulated time advanced by at most one update while suspended: " + on[0] + " s");
        assertTrue(on[1] <= 0.001, "no model moved more than 1 mm while suspended: " + on[1] + " m");
        double[] off = suspendedFiveSecondsInTheTwoRobotWorld(false);
        report(String.format(java.util.Locale.ROOT, "frozen world off, suspended 5 s: simulated time +%.3f s, r1 (Stage's controller) "
                + "moved %.3f m", off[0], off[3]));
        assertTrue(off[0] > 3.0, "with the option off simulated time runs on: " + off[0] + " s");
        assertTrue(off[3] > 0.1, "with the option off r1 drives on: " + off[3] + " m");
    }

    /**
     * One suspension of 5 s in two-robots.cfg: [simulated time advanced (s), largest move of either robot (m), hold to
     * world frozen (ms, or -1), r1's move (m)]; after Resume, waits until both robots move again and time runs.
     */
    private double[] suspendedFiveSecondsInTheTwoRobotWorld(boolean freeze) throws Exception {
        DebugPlugin.getDefault().getBreakpointManager().removeBreakpoints(
                DebugPlugin.getDefault().getBreakpointManager().getBreakpoints(), true); // the earlier run's
        IFile robot = write(project, "robot.py", ROBOT);
        int line = lineOf(ROBOT, BREAK_MARK);
        breakpointAsPyDevsRulerMakesIt(robot, line);
        Path mark = tmp.resolve("mark-" + freeze);
        try (DebugEvents events = new DebugEvents()) {
            ILaunchConfigurationWorkingCopy wc = config(true, false, 500, Map.of("MARK_EVERY", "2.5", "MARKS", "1", "MARK",
                    mark.toString()));
            wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/two-robots.cfg").getFullPath().toString());
            wc.setAttribute(LaunchAttributes.FREEZE_WORLD, freeze);
            ILaunch launch = launch(wc, ILaunchManager.DEBUG_MODE);
            SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
            assertNotNull(parts, "the launch is a running Robot Session");
            WorldFreeze world = parts.session().world();
            assertEquals(freeze, world != null, "a world driver exactly when the option is on: " + parts.session().worldProblem());
            long[] heldAt = {-1};
            long[] frozenAt = {-1};
            if (world != null) {
                world.addListener((state, problem) -> {
                    if (state.frozen() && frozenAt[0] < 0) {
                        frozenAt[0] = System.nanoTime();
                    }
                });
                SessionHolds.of(launch).hold().addListener(st -> {
                    if (st.held() && heldAt[0] < 0) {
                        heldAt[0] = System.nanoTime();
                    }
                });
            }
            int moved = parts.session().portMap().values().iterator().next();
            Path script = Files.writeString(tmp.resolve("world-poses.py"), WORLD_POSES);
            Proc poses = start("world poses", List.of(python, "-u", script.toString(), String.valueOf(moved)), Map.of("PYTHONPATH",
                    clientFolder()));
            DebugEvent suspend = events.await("the suspension at the breakpoint", WAIT, e -> e.getKind() == DebugEvent.SUSPEND
                    && e.getDetail() == DebugEvent.BREAKPOINT && e.getSource() instanceof IThread);
            long arrival = events.arrival(suspend)[0];
            IThread thread = (IThread) suspend.getSource();
            assertEquals(line, thread.getTopStackFrame().getLineNumber(), "suspended at the breakpoint's line");
            if (freeze) {
                Await.until("the world to freeze", WAIT, () -> world.last() != null && world.last().frozen(), poses::output);
            }
            // the suspension under test: from 0.5 s after the SUSPEND event (the hold and the freeze are done by then) for 5 s
            long from = arrival + 500 * MS;
            long until = from + 5000 * MS;
            Await.until("world samples for 5 s of the suspension", Duration.ofSeconds(30),
                    () -> worldSamples(poses).stream().anyMatch(w -> w[0] > until), poses::output);
            List<double[]> window = worldSamples(poses).stream().filter(w -> w[0] >= from && w[0] <= until).toList();
            assertTrue(window.size() > 20, "sampled the world through the suspension: " + window.size());
            double[] first = window.get(0);
            double maxMove = 0;
            for (double[] w : window) {
                maxMove = Math.max(maxMove, Math.max(Math.hypot(w[2] - first[2], w[3] - first[3]), Math.hypot(w[4] - first[4], w[5] - first[5])));
            }
            double[] last = window.get(window.size() - 1);
            double timeAdvanced = last[1] - first[1];
            double r1Moved = Math.hypot(last[4] - first[4], last[5] - first[5]);
            assertTrue(SessionHolds.of(launch).hold().isHeld(), "still held at the end of the window");
            thread.resume();
            DebugEvent resume = events.await("the resume", WAIT, e -> e.getSource() == thread && e.getKind() == DebugEvent.RESUME);
            long resumed = events.arrival(resume)[0];
            Await.until("both robots to move and time to run after Resume", WAIT, () -> {
                List<double[]> after = worldSamples(poses).stream().filter(w -> w[0] > resumed).toList();
                if (after.size() < 2) {
                    return false;
                }
                double[] a = after.get(0);
                double[] b = after.get(after.size() - 1);
                return b[1] > a[1] && Math.hypot(b[2] - a[2], b[3] - a[3]) > 0.05 && Math.hypot(b[4] - a[4], b[5] - a[5]) > 0.05;
            }, poses::output);
            launch.terminate();
            Await.until("the session to end", WAIT, () -> launch.isTerminated() && parts.session().isClosed(), () -> "");
            poses.close();
            procs.remove(poses);
            if (freeze) {
                try (SpyLogReader r = SpyLogReader.open(spyLog())) {
                    List<HoldEntry> holds = r.holdEntries();
                    assertTrue(holds.stream().anyMatch(e -> e.action() == HoldEntry.Action.WORLD_FROZEN
                            && e.text().contains("suspended in the debugger")), "the freeze is in the spy log: " + holds);
                    assertTrue(holds.stream().anyMatch(e -> e.action() == HoldEntry.Action.WORLD_THAWED), "the thaw is in the spy log");
                }
                Files.delete(spyLog()); // the next run's session writes the one log again
            }
            return new double[] { timeAdvanced, maxMove, frozenAt[0] > 0 && heldAt[0] > 0 ? (frozenAt[0] - heldAt[0]) / 1e6 : -1,
                    r1Moved };
        }
    }

    /** The world reader's samples: [monotonic ns, simulated time s, r0 x, r0 y, r1 x, r1 y]. */
    private static List<double[]> worldSamples(Proc poses) {
        List<double[]> out = new ArrayList<>();
        for (String l : poses.lines) {
            if (l.startsWith("WORLD ")) {
                String[] f = l.split(" ");
                out.add(new double[] { Long.parseLong(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3]), Double.parseDouble(f[4]),
                        Double.parseDouble(f[5]), Double.parseDouble(f[6]) });
            }
        }
        return out;
    }

    @Test
    void withTheHoldOffTheSuspendedProgramsRobotDrivesOn() throws Exception {
        Suspension s = suspendAtBreakpoint(false, 1).get(0);
        assertTrue(s.speedBefore > 0.2, "the robot drove before the breakpoint: " + s);
        assertTrue(s.moved3s > 0.6, "without the hold the robot drove on at ~0.3 m/s while the program was suspended: " + s);
        assertFalse(s.holdingWhileSuspended, "no hold: " + s);
        assertTrue(s.injectedMs < 0, "nothing was injected: " + s);
    }

    @Test
    void theEmergencyStopStopsTheRealRobotAndReleaseLetsItDriveOn() throws Exception {
        Path mark = tmp.resolve("mark");
        ILaunch launch = launch(config(true, false, 500, Map.of("MARK_EVERY", "3.0", "MARKS", "1", "MARK", mark.toString())),
                ILaunchManager.RUN_MODE);
        HoldTimes times = holdTimes(launch); // before the pose reader's start: the hold may come while it starts
        Poses poses = poses(launch);
        long at = Long.parseLong(awaitFile(mark.resolveSibling("mark1")).trim());
        poses.awaitSampleAfter(at + 500 * MS);
        double speed = poses.speed(at - 1000 * MS, at);
        long engaged = System.nanoTime();
        EmergencyStop.get().engage();
        long heldAt = times.awaitHeld(HoldReason.EMERGENCY_STOP);
        poses.awaitSampleAfter(engaged + 3300 * MS);
        Stop stop = poses.stopAfter(engaged);
        assertTrue(SessionHolds.of(launch).hold().state().reasons().containsKey(HoldReason.EMERGENCY_STOP));
        long released = System.nanoTime();
        EmergencyStop.get().release();
        long moved = poses.awaitMovedAfter(released, stop.still, 0.05);
        String line = String.format(Locale.ROOT, "emergency stop: speed before %.3f m/s; engage -> held %.1f ms; %.3f m further after engage "
                + "(pose still from %d ms); drift while held 3 s %.4f m; moved 5 cm %d ms after release", speed,
                (heldAt - engaged) / 1e6, stop.toStill, stop.stillFromMs, stop.drift, (moved - released) / MS);
        report(line);
        assertTrue(speed > 0.2, line);
        assertTrue(stop.toStill < 0.06, "stopped within 200 ms, less than 6 cm further: " + line);
        assertTrue(stop.drift < 0.01, "still for 3 s: " + line);
    }

    @Test
    void theSilenceWatchdogStopsTheRobotOfAProgramThatGoesSilentAndReleasesItWhenItSendsAgain() throws Exception {
        Path mark = tmp.resolve("mark");
        ILaunch launch = launch(config(true, true, 500, Map.of("MARK_EVERY", "3.0", "MARKS", "1", "MARK", mark.toString(),
                "SILENCE", "5")), ILaunchManager.RUN_MODE);
        HoldTimes times = holdTimes(launch); // before the pose reader's start: the hold may come while it starts
        Poses poses = poses(launch);
        long silent = Long.parseLong(awaitFile(mark.resolveSibling("mark1")).trim());
        long heldAt = times.awaitHeld(HoldReason.WATCHDOG);
        poses.awaitSampleAfter(silent + 4500 * MS);
        double speed = poses.speed(silent - 1000 * MS, silent);
        // the watchdog fires between 500 and 625 ms after the last command; the robot must be still from 800 ms
        Stop stop = poses.stopFrom(silent, 800 * MS, 3500 * MS);
        long moved = poses.awaitMovedAfter(silent + 5000 * MS, stop.still, 0.05);
        String line = String.format(Locale.ROOT, "watchdog 500 ms: speed before %.3f m/s; silent -> held %.1f ms; %.3f m from going silent "
                + "to still; drift while held (0.8-4.3 s) %.4f m; moved again %d ms after the program's silence ended", speed,
                (heldAt - silent) / 1e6, stop.toStill, stop.drift, (moved - silent) / MS - 5000);
        report(line);
        assertTrue(speed > 0.2, line);
        assertTrue(heldAt - silent >= 400 * MS && heldAt - silent < 800 * MS, "held by the watchdog ~500 ms after the silence began: " + line);
        assertTrue(stop.toStill < 0.3, "stopped, not driven on through the silence (driving on: 0.24 m at 0.8 s, 1.3 m at 4.3 s): " + line);
        assertTrue(stop.drift < 0.01, "still while silent: " + line);
    }

    /**
     * Issue 27's robot data breakpoint on the real things: a program drives the Pioneer at a wall at 0.4 m/s reading
     * the laser, with {@code laser:0 min(ranges) < 0.8} set in the workbench. Every run: the program is suspended, at
     * the first scan nearer than 0.8 m (the scan before it on the wire was not), the program read exactly that scan,
     * no motion command reached Player between the hit and Resume, and the robot stood still. Between runs, while
     * suspended, the robot is put 1 m back along its path through Stage's simulation interface.
     */
    @Test
    void aRobotDataBreakpointSuspendsTheProgramAtTheFirstScanNearerThan08mEveryRun() throws Exception {
        int runs = 20;
        Path scans = tmp.resolve("scans.txt");
        IFile robot = write(project, "robot.py", TO_THE_WALL);
        WorkbenchShot.arrangeForDebugging(robot);
        var breakpoint = org.stagecraft.tools.ui.breakpoints.RobotDataBreakpoint.create("laser:0 min(ranges) < 0.8", 0);
        List<double[]> figures = new ArrayList<>(); // per run: hit -> SUSPEND ms, drift m, held-back commands
        ILaunch launch;
        try (DebugEvents events = new DebugEvents()) {
            launch = launch(config(true, false, 500, Map.of("SCANS", scans.toString())), ILaunchManager.DEBUG_MODE);
            SessionHolds holds = SessionHolds.of(launch);
            assertNotNull(holds.dataBreakpoints(), "robot data breakpoints are on with the holds");
            var spy = holds.dataBreakpoints().spy();
            Await.until("the workbench's breakpoint on the session's spy", WAIT, () -> spy.breakpoints().size() == 1, () -> "");
            Poses poses = poses(launch);
            int moved = RobotSessionLaunchDelegate.partsOf(launch).session().portMap().values().iterator().next();
            DebugEvent last = null;
            for (int n = 1; n <= runs; n++) {
                DebugEvent prev = last;
                DebugEvent suspend = events.await("suspension #" + n + " at the robot data breakpoint", WAIT, e -> e != prev
                        && e.getKind() == DebugEvent.SUSPEND && e.getSource() instanceof IThread
                        && (prev == null || events.arrival(e)[0] > events.arrival(prev)[0]));
                last = suspend;
                long arrival = events.arrival(suspend)[0];
                var hit = spy.current();
                assertNotNull(hit, "suspended by the robot data breakpoint (run " + n + ")");
                // the session's debug listener passes it on at this same SUSPEND event, maybe after ours has it
                Await.until("the hit's message to go on to the program", WAIT, hit::passedOn, () -> "");
                IThread thread = (IThread) suspend.getSource();
                String where = thread.getTopStackFrame() == null ? "?" : thread.getTopStackFrame().getName();
                poses.awaitSampleAfter(arrival + 1200 * MS);
                Stop stop = poses.stopFrom(arrival, 200 * MS, 1200 * MS);
                assertTrue(holds.hold().reasons().containsKey(HoldReason.DATA_BREAKPOINT), holds.hold().reasons().toString());
                figures.add(new double[] { (arrival - hit.foundNanos()) / 1e6, stop.drift });
                report(String.format(Locale.ROOT, "data breakpoint run %d: %s; message -> SUSPEND %.1f ms (passed on: %s); "
                        + "drift while suspended (0.2-1.2 s) %.4f m; stopped in %s", n, hit.why(), (arrival - hit.foundNanos()) / 1e6,
                        hit.passedOnWhy(), stop.drift, where));
                assertTrue(stop.drift < 0.01, "the robot stood still while suspended: " + stop.drift + " m");
                if (n == 1) {
                    Await.until("the breakpoint to show its hit", WAIT, () -> !breakpoint.lastHit().isEmpty(), () -> "");
                    Path png = reportDir().resolve("screenshots/robot-data-breakpoint.png");
                    int colours = WorkbenchShot.captureDataBreakpoint(thread, png);
                    assertTrue(colours > 50, "a real picture: " + colours + " colours in " + png);
                    report("screenshot at the robot data breakpoint: " + png.toAbsolutePath());
                    // the Robot View marks the reading: the laser, and the beam of the nearest return
                    org.stagecraft.scene.BreakReading marked = WorkbenchShot.markedReading();
                    float[] ranges = ((org.stagecraft.player.msg.Laser.Scan) new org.stagecraft.player.codec.PlayerDecoder(
                            org.stagecraft.player.codec.CodecRegistry.standard()).decode(hit.header(), java.util.Arrays.copyOfRange(
                                    hit.message(), org.stagecraft.player.wire.MessageHeader.SIZE, hit.message().length)).body()).ranges().toArray();
                    int nearest = 0;
                    for (int i = 1; i < ranges.length; i++) {
                        nearest = ranges[i] < ranges[nearest] ? i : nearest;
                    }
                    assertTrue(marked != null && marked.device().interf() == org.stagecraft.player.msg.Laser.CODE
                            && marked.decidingFields().equals(List.of("ranges[" + nearest + "]")),
                            "the Robot View marks beam " + nearest + " of the laser: " + marked);
                    report("the Robot View marks " + marked.device() + " " + marked.decidingFields() + " (" + ranges[nearest] + " m)");
                }
                // 1 m back along the path, for the next run
                Sample at = poses.at(arrival + 1200 * MS);
                double heading = Math.toRadians(45);
                Path teleport = Files.writeString(tmp.resolve("teleport.py"), TELEPORT);
                Map<String, String> env = new HashMap<>();
                env.put("PYTHONPATH", clientFolder());
                Proc t = start("teleport", List.of(python, "-u", teleport.toString(), String.valueOf(moved),
                        String.valueOf(at.x() - Math.cos(heading)), String.valueOf(at.y() - Math.sin(heading)), String.valueOf(heading)), env);
                Await.until("the robot to be put back", WAIT, () -> t.lines.contains("MOVED"), t::output);
                // as a user would: disabled while the program reads what Player queued before the robot was put back,
                // enabled again once it drives from its new place
                breakpoint.setEnabled(false);
                Await.until("the breakpoint disabled on the spy", WAIT, () -> !spy.breakpoints().get(0).enabled(), () -> "");
                long resumed = System.nanoTime();
                thread.resume();
                Await.until("the hit to end on Resume", WAIT, () -> spy.current() == null, () -> String.valueOf(spy.current()));
                Sample back = new Sample(resumed, at.x() - Math.cos(heading), at.y() - Math.sin(heading));
                poses.awaitMovedAfter(resumed, back, 0.1);
                breakpoint.setEnabled(true);
                Await.until("the breakpoint enabled on the spy", WAIT, () -> spy.breakpoints().get(0).enabled(), () -> "");
            }
            SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
            launch.terminate();
            Await.until("the session to end", WAIT, () -> launch.isTerminated() && parts.session().isClosed(), () -> "");
            checkDataBreakpointsInTheLog(runs, Files.readString(scans));
            // the picture of the inspector at the first triggering message, in the Session Log editor (docs/debugging-robots.md)
            long triggering = -1;
            try (SpyLogReader r = SpyLogReader.open(spyLog())) {
                HoldEntry first = r.holdEntries().stream().filter(e -> e.action() == HoldEntry.Action.BREAK).findFirst().orElseThrow();
                for (var it = r.entries(); it.hasNext() && triggering < 0;) {
                    if (it.next() instanceof org.stagecraft.spy.log.LogEntry.Wire w && w.conn() == first.conn()
                            && w.dir() == org.stagecraft.player.wire.Direction.SERVER_TO_CLIENT && w.streamOffset() == first.programOffset()) {
                        triggering = w.timeNanos();
                    }
                }
            }
            assertTrue(triggering > 0, "the triggering message is in the log's wire channel");
            Path png = reportDir().resolve("screenshots/robot-data-breakpoint-inspector.png");
            int colours = WorkbenchShot.captureAt(project, triggering, png);
            assertTrue(colours > 50, "a real picture, not a blank screen: " + colours + " colours in " + png);
            report("screenshot of the inspector at the triggering message: " + png.toAbsolutePath());
        }
        double[] ms = figures.stream().mapToDouble(f -> f[0]).sorted().toArray();
        report(String.format(Locale.ROOT, "data breakpoint: %d of %d runs suspended at the first scan nearer than 0.8 m; message at the spy "
                + "-> SUSPEND p50 %.1f ms, p99 %.1f ms, max %.1f ms", runs, runs, ms[ms.length / 2],
                ms[Math.min(ms.length - 1, (int) Math.ceil(ms.length * 0.99) - 1)], ms[ms.length - 1]));
    }

    /** From the spy log: each hit at the first scan below 0.8 m, read by the program, and nothing moved the robot meanwhile. */
    private void checkDataBreakpointsInTheLog(int runs, String programOut) throws IOException {
        try (SpyLogReader r = SpyLogReader.open(spyLog())) {
            List<HoldEntry> holds = r.holdEntries();
            List<HoldEntry> breaks = holds.stream().filter(e -> e.action() == HoldEntry.Action.BREAK).toList();
            assertEquals(runs, breaks.size(), "one hit per run");
            var decoder = new org.stagecraft.player.codec.PlayerDecoder(org.stagecraft.player.codec.CodecRegistry.standard());
            // every laser scan on the program's connection: offset -> [nearest, timestamp]
            java.util.TreeMap<Long, double[]> scans = new java.util.TreeMap<>();
            List<long[]> commands = new ArrayList<>(); // [time, offset] of the program's motion commands
            for (var it = r.entries(); it.hasNext();) {
                if (it.next() instanceof org.stagecraft.spy.log.LogEntry.Wire w && w.kind() == org.stagecraft.spy.log.LogEntry.Kind.FRAME
                        && w.conn() == breaks.get(0).conn()) {
                    var h = org.stagecraft.player.wire.MessageHeader.read(w.bytes(), 0);
                    byte[] payload = Arrays.copyOfRange(w.bytes(), org.stagecraft.player.wire.MessageHeader.SIZE, w.bytes().length);
                    if (w.dir() == org.stagecraft.player.wire.Direction.SERVER_TO_CLIENT && h.interf() == 6 && h.type() == 1
                            && decoder.decode(h, payload).body() instanceof org.stagecraft.player.msg.Laser.Scan scan) {
                        float min = Float.POSITIVE_INFINITY;
                        for (float f : scan.ranges().toArray()) {
                            min = Math.min(min, f);
                        }
                        scans.put(w.streamOffset(), new double[] { min, h.timestamp() });
                    } else if (w.dir() == org.stagecraft.player.wire.Direction.CLIENT_TO_SERVER && h.interf() == 4 && h.type() == 2) {
                        commands.add(new long[] { w.timeNanos(), w.streamOffset() });
                    }
                }
            }
            // the robots held at the message itself: the zero command's time after each hit, on the spy's clock
            double[] toZero = breaks.stream().mapToDouble(b -> holds.stream().filter(e -> e.action() == HoldEntry.Action.INJECTED
                    && e.timeNanos() >= b.timeNanos()).mapToLong(e -> e.timeNanos() - b.timeNanos()).min().orElse(Long.MAX_VALUE) / 1e6)
                    .sorted().toArray();
            assertTrue(toZero[toZero.length - 1] < 50, "zero velocity went to Player within 50 ms of every hit: " + Arrays.toString(toZero));
            report(String.format(Locale.ROOT, "data breakpoint: message at the spy -> zero CMD_VEL to Player (spy log) p50 %.2f ms, max %.2f ms",
                    toZero[toZero.length / 2], toZero[toZero.length - 1]));
            // and the world frozen after it (the world driver's answer, logged by the session on the spy's clock)
            double[] toFrozen = breaks.stream().mapToDouble(b -> holds.stream().filter(e -> e.action() == HoldEntry.Action.WORLD_FROZEN
                    && e.timeNanos() >= b.timeNanos()).mapToLong(e -> e.timeNanos() - b.timeNanos()).min().orElse(Long.MAX_VALUE) / 1e6)
                    .sorted().toArray();
            assertTrue(toFrozen[toFrozen.length - 1] < 1000, "the world froze within a second of every hit: " + Arrays.toString(toFrozen));
            report(String.format(Locale.ROOT, "data breakpoint: message at the spy -> world frozen (spy log) p50 %.1f ms, p99 %.1f ms, max %.1f ms",
                    toFrozen[toFrozen.length / 2], toFrozen[(int) Math.ceil(toFrozen.length * 0.99) - 1], toFrozen[toFrozen.length - 1]));
            java.util.Set<Long> heldBack = new java.util.HashSet<>();
            holds.stream().filter(e -> e.action() == HoldEntry.Action.HELD_BACK).forEach(e -> heldBack.add(e.programOffset()));
            for (HoldEntry b : breaks) {
                double[] hit = scans.get(b.programOffset());
                assertNotNull(hit, "the hit is a laser scan at " + b.programOffset());
                assertTrue(hit[0] < 0.8, "below 0.8 m: " + hit[0]);
                var before = scans.lowerEntry(b.programOffset());
                assertTrue(before != null && before.getValue()[0] >= 0.8, "the scan before it was not below 0.8 m: "
                        + (before == null ? "none" : before.getValue()[0]));
                assertTrue(programOut.contains("scan " + hit[1] + " "), "the program read the triggering scan (time " + hit[1] + ")");
                HoldEntry off = holds.stream().filter(e -> e.action() == HoldEntry.Action.HOLD_OFF && e.timeNanos() > b.timeNanos())
                        .findFirst().orElseThrow();
                for (long[] c : commands) {
                    if (c[0] > b.timeNanos() && c[0] < off.timeNanos()) {
                        assertTrue(heldBack.contains(c[1]), "no motion command reached Player between the hit and Resume: byte " + c[1]);
                    }
                }
            }
        }
    }

    // ------------------------------------------------------------------------------------------ suspension

    /** What one suspension at the breakpoint showed. */
    record Suspension(boolean hold, int n, double speedBefore, double toStill, long stillFromMs, double drift, double moved3s,
            boolean holdingWhileSuspended, double heldMs, double injectedMs, long resumeMovedMs) {
        String figures() {
            return String.format(Locale.ROOT, "suspend %s #%d: speed before %.3f m/s; SUSPEND -> zero CMD_VEL on the wire (spy log) %s; "
                    + "SUSPEND -> hold listener %s; moved from SUSPEND to the first pose after 200 ms %.3f m (at %d ms); then while suspended 3 s "
                    + "%.4f m (the farthest from that pose); moved in the 3.2 s %.3f m; moved 5 cm %d ms after RESUME", hold ? "with hold" : "WITHOUT hold", n, speedBefore,
                    injectedMs < 0 ? "none" : String.format(Locale.ROOT, "%.2f ms", injectedMs),
                    heldMs < 0 ? "none" : String.format(Locale.ROOT, "%.2f ms", heldMs), toStill, stillFromMs, drift, moved3s, resumeMovedMs);
        }
    }

    private List<Suspension> suspendAtBreakpoint(boolean hold, int marks) throws Exception {
        Path mark = tmp.resolve("mark");
        IFile robot = write(project, "robot.py", ROBOT);
        int line = lineOf(ROBOT, BREAK_MARK);
        breakpointAsPyDevsRulerMakesIt(robot, line);
        List<Suspension> out = new ArrayList<>();
        List<long[]> suspendTimes = new ArrayList<>();
        boolean pictures = hold && marks > 1;
        if (pictures) {
            WorkbenchShot.arrangeForDebugging(robot); // the Debug view open before the suspensions, as a user has it
        }
        ILaunch launch;
        try (DebugEvents events = new DebugEvents()) {
            launch = launch(config(hold, false, 500, Map.of("MARK_EVERY", "2.5", "MARKS", String.valueOf(marks), "MARK", mark.toString())),
                    ILaunchManager.DEBUG_MODE);
            HoldTimes times = holdTimes(launch); // before the pose reader's start: the hold may come while it starts
            Poses poses = poses(launch);
            SessionHolds holds = SessionHolds.of(launch);
            assertEquals(hold, holds.hold().isEnabled(), "holds are enabled exactly when the option is on");
            DebugEvent last = null;
            for (int n = 1; n <= marks; n++) {
                DebugEvent prev = last;
                DebugEvent suspend = events.await("suspension #" + n + " at the breakpoint", WAIT, e -> e != prev
                        && e.getKind() == DebugEvent.SUSPEND && e.getDetail() == DebugEvent.BREAKPOINT && e.getSource() instanceof IThread
                        && (prev == null || events.arrival(e)[0] > events.arrival(prev)[0]));
                last = suspend;
                long[] arrival = events.arrival(suspend);
                IThread thread = (IThread) suspend.getSource();
                assertEquals(line, thread.getTopStackFrame().getLineNumber(), "suspended at the breakpoint's line");
                poses.awaitSampleAfter(arrival[0] + 3300 * MS);
                boolean holding = holds.suspendHold() != null && holds.suspendHold().isHolding() && holds.hold().isHeld();
                long heldAt = times.firstHeldAfter(arrival[0] - 1000 * MS, HoldReason.SUSPENDED);
                double speed = poses.speed(arrival[0] - 1000 * MS, arrival[0]);
                Stop stop = poses.stopFrom(arrival[0], 200 * MS, 3200 * MS);
                double moved3s = Poses.dist(poses.at(arrival[0]), poses.at(arrival[0] + 3200 * MS));
                if (pictures && (n == 1 || n == marks)) {
                    // the pictures, after the measurement window: at the first suspension the program in PyDev's editor at the
                    // breakpoint, the Debug view and the held robot (docs/tool-manager.md); at the last, the spy log in the
                    // Session Log editor with the earlier suspensions' holds on its timeline (docs/debugging-robots.md)
                    Path png = reportDir().resolve(n == 1 ? "screenshots/pydev-robot-session.png" : "screenshots/debugging-robots.png");
                    int colours = n == 1 ? WorkbenchShot.captureDebugging(robot, thread, png) : WorkbenchShot.capture(project, png);
                    assertTrue(colours > 50, "a real picture, not a blank screen: " + colours + " colours in " + png);
                    assertTrue(holds.hold().isHeld(), "still held while the views opened");
                    report("screenshot while suspended and held: " + png.toAbsolutePath() + " (Robot View: " + WorkbenchShot.robots() + ")");
                }
                thread.resume();
                DebugEvent resume = events.await("resume #" + n, WAIT, e -> e.getSource() == thread && e.getKind() == DebugEvent.RESUME
                        && events.arrival(e)[0] > arrival[0]);
                long resumed = events.arrival(resume)[0];
                long moved = poses.awaitMovedAfter(resumed, poses.at(resumed), 0.05);
                suspendTimes.add(arrival);
                out.add(new Suspension(hold, n, speed, stop.toStill, stop.stillFromMs, stop.drift, moved3s, holding,
                        heldAt < 0 ? -1 : (heldAt - arrival[0]) / 1e6, -1, (moved - resumed) / MS));
            }
            SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
            launch.terminate();
            Await.until("the session to end", WAIT, () -> launch.isTerminated() && parts.session().isClosed(), () -> "");
        }
        // the zero commands on the wire: the spy log's INJECTED entries (the spy's wall clock, epoch nanoseconds)
        List<HoldEntry> injected = injectedEntries();
        List<Suspension> withWire = new ArrayList<>();
        for (int i = 0; i < out.size(); i++) {
            Suspension s = out.get(i);
            long epoch = suspendTimes.get(i)[1];
            double ms = injected.stream().filter(e -> e.timeNanos() >= epoch - 1000 * MS && e.timeNanos() <= epoch + 3000 * MS)
                    .mapToDouble(e -> (e.timeNanos() - epoch) / 1e6).findFirst().orElse(-1);
            Suspension w = new Suspension(s.hold, s.n, s.speedBefore, s.toStill, s.stillFromMs, s.drift, s.moved3s, s.holdingWhileSuspended,
                    s.heldMs, ms, s.resumeMovedMs);
            report(w.figures());
            withWire.add(w);
        }
        if (!hold) {
            assertTrue(injected.isEmpty(), "the spy injected nothing with holds off: " + injected);
        }
        return withWire;
    }

    /** The session's one spy log, in the project's log folder. */
    private Path spyLog() throws IOException {
        Path logs = project.getLocation().toPath().resolve("logs");
        List<Path> files;
        try (Stream<Path> s = Files.list(logs)) {
            files = s.filter(p -> p.toString().endsWith(".mcap")).toList();
        }
        assertEquals(1, files.size(), "one spy log: " + files);
        return files.get(0);
    }

    private List<HoldEntry> injectedEntries() throws IOException {
        try (SpyLogReader r = SpyLogReader.open(spyLog())) {
            return r.holdEntries().stream().filter(e -> e.action() == HoldEntry.Action.INJECTED).toList();
        }
    }

    private static Path reportDir() {
        String file = System.getProperty("stagecraft.holdReport");
        return file == null || file.isBlank() || file.startsWith("${") ? Path.of("") : Path.of(file).toAbsolutePath().getParent();
    }

    private static void report(String line) {
        REPORT.add(line);
        System.out.println("[hold figures] " + line);
    }

    // ------------------------------------------------------------------------------------------ poses

    record Sample(long t, double x, double y) {
    }

    /** How the robot came to a stop: the distance until still, from when, and the drift afterwards. */
    record Stop(double toStill, long stillFromMs, double drift, Sample still) {
    }

    /** r0's poses from Stage (the simulation interface), as the pose reader prints them. */
    final class Poses {
        final Proc proc;

        Poses(Proc proc) {
            this.proc = proc;
        }

        List<Sample> samples() {
            List<Sample> out = new ArrayList<>();
            for (String l : proc.lines) {
                if (l.startsWith("POSE ")) {
                    String[] f = l.split(" ");
                    out.add(new Sample(Long.parseLong(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3])));
                }
            }
            return out;
        }

        void awaitSampleAfter(long t) {
            Await.until("a pose sampled after " + t, WAIT, () -> {
                List<Sample> s = samples();
                return !s.isEmpty() && s.get(s.size() - 1).t() > t;
            }, proc::output);
        }

        /** The newest sample taken at or before {@code t}. */
        Sample at(long t) {
            Sample best = null;
            for (Sample s : samples()) {
                if (s.t() <= t) {
                    best = s;
                }
            }
            if (best == null) {
                fail("no pose sampled before " + t + ": " + proc.output());
            }
            return best;
        }

        double speed(long from, long to) {
            Sample a = at(from);
            Sample b = at(to);
            return dist(a, b) / ((b.t() - a.t()) / 1e9);
        }

        /** From {@code t0}: the first sample at or after {@code t0 + still}, how far it is from the pose at t0, the drift until {@code t0 + until}. */
        Stop stopFrom(long t0, long still, long until) {
            Sample start = at(t0);
            Sample first = samples().stream().filter(s -> s.t() >= t0 + still).findFirst().orElseThrow();
            double drift = samples().stream().filter(s -> s.t() >= first.t() && s.t() <= t0 + until).mapToDouble(s -> dist(first, s))
                    .max().orElse(0);
            return new Stop(dist(start, first), (first.t() - t0) / MS, drift, first);
        }

        Stop stopAfter(long t0) {
            return stopFrom(t0, 200 * MS, 3200 * MS);
        }

        /** When (the sample time) the robot was first {@code metres} away from {@code from}, after {@code t}; waits for it. */
        long awaitMovedAfter(long t, Sample from, double metres) {
            long[] when = {-1};
            Await.until("the robot to move " + metres + " m from " + from, Duration.ofSeconds(15), () -> {
                for (Sample s : samples()) {
                    if (s.t() > t && dist(from, s) >= metres) {
                        when[0] = s.t();
                        return true;
                    }
                }
                return false;
            }, proc::output);
            return when[0];
        }

        static double dist(Sample a, Sample b) {
            return Math.hypot(a.x() - b.x(), a.y() - b.y());
        }
    }

    private Poses poses(ILaunch launch) throws IOException {
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
        assertNotNull(parts, "the launch is a running Robot Session");
        int moved = parts.session().portMap().values().iterator().next();
        Path script = Files.writeString(tmp.resolve("poses.py"), POSES);
        Map<String, String> env = new HashMap<>();
        env.put("PYTHONPATH", clientFolder());
        Proc p = start("poses", List.of(python, "-u", script.toString(), String.valueOf(moved)), env);
        Poses poses = new Poses(p);
        Await.until("the pose reader to read a pose from Player's simulation interface", WAIT,
                () -> !poses.samples().isEmpty(), p::output);
        return poses;
    }

    private static String clientFolder() {
        return org.stagecraft.tools.ui.launch.PythonClientPath.folder()
                .orElseThrow(() -> new AssertionError("the bundled stagecraft_player client is not found"));
    }

    // ------------------------------------------------------------------------------------------ hold times

    /** When (System.nanoTime) the session's RobotHold reported each held state, from its HoldListener. */
    static final class HoldTimes implements HoldListener {
        final List<Object[]> changes = new CopyOnWriteArrayList<>();

        @Override
        public void holdChanged(HoldState state) {
            changes.add(new Object[] {System.nanoTime(), state});
        }

        long firstHeldAfter(long t, HoldReason reason) {
            for (Object[] c : changes) {
                HoldState s = (HoldState) c[1];
                if ((long) c[0] >= t && s.held() && s.reasons().containsKey(reason)) {
                    return (long) c[0];
                }
            }
            return -1;
        }

        long awaitHeld(HoldReason reason) {
            Await.until("a hold with reason " + reason, WAIT, () -> firstHeldAfter(0, reason) >= 0, () -> changes.toString());
            return firstHeldAfter(0, reason);
        }
    }

    private static HoldTimes holdTimes(ILaunch launch) {
        HoldTimes t = new HoldTimes();
        SessionHolds.of(launch).hold().addListener(t);
        return t;
    }

    // ------------------------------------------------------------------------------------------ the session

    private ILaunchConfigurationWorkingCopy config(boolean holdWhenSuspended, boolean watchdog, int watchdogMillis,
            Map<String, String> programEnv) throws Exception {
        IFile robot = project.getFile("robot.py");
        if (!robot.exists()) {
            robot = write(project, "robot.py", ROBOT);
        }
        int port = freePort();
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("realhold"));
        wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/pioneer-laser-sonar.cfg").getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, playerStagePrefix().resolve("bin/player").toString());
        Map<String, String> env = new HashMap<>(playerEnv);
        env.put("DISPLAY", ":" + display);
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, env);
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, port);
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "logs");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        wc.setAttribute(LaunchAttributes.PROGRAM, robot.getFullPath().toString());
        wc.setAttribute(LaunchAttributes.HOLD_WHEN_SUSPENDED, holdWhenSuspended);
        wc.setAttribute(LaunchAttributes.WATCHDOG, watchdog);
        wc.setAttribute(LaunchAttributes.WATCHDOG_MILLIS, watchdogMillis);
        Map<String, String> penv = new HashMap<>(programEnv);
        penv.put("ROBOT_PORT", String.valueOf(port));
        wc.setAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, penv);
        return wc;
    }

    private ILaunch launch(ILaunchConfigurationWorkingCopy wc, String mode) throws Exception {
        ILaunch l = wc.launch(mode, new NullProgressMonitor());
        launches.add(l);
        return l;
    }

    private String awaitFile(Path f) throws IOException {
        Await.until("the robot program to write " + f, WAIT, () -> Files.exists(f), () -> launches.stream()
                .flatMap(l -> Arrays.stream(l.getProcesses())).map(p -> p.getLabel() + ": " + p.getStreamsProxy()
                        .getOutputStreamMonitor().getContents() + p.getStreamsProxy().getErrorStreamMonitor().getContents()).toList().toString());
        return Files.readString(f);
    }

    private static int lineOf(String text, String marker) {
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].contains(marker)) {
                return i + 1;
            }
        }
        throw new AssertionError(marker);
    }

    private static void breakpointAsPyDevsRulerMakesIt(IFile file, int line) throws Exception {
        Exception[] failure = {null};
        Display.getDefault().syncExec(() -> {
            try {
                IEditorPart editor = IDE.openEditor(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage(), file);
                ITextEditor text = (ITextEditor) editor;
                IDocument doc = text.getDocumentProvider().getDocument(text.getEditorInput());
                PyBreakpointRulerAction.addBreakpointMarker(doc, line, text, PyBreakpoint.PY_BREAK_TYPE_PYTHON);
            } catch (Exception e) {
                failure[0] = e;
            }
        });
        if (failure[0] != null) {
            throw failure[0];
        }
        assertEquals(1, Arrays.stream(DebugPlugin.getDefault().getBreakpointManager().getBreakpoints())
                .filter(b -> b.getMarker() != null && file.equals(b.getMarker().getResource())).count());
    }

    // ------------------------------------------------------------------------------------------ Player/Stage

    private static Path playerStagePrefix() {
        String p = System.getProperty("stagecraft.playerStage", "");
        if (p.isBlank() || p.startsWith("${")) {
            fail("-Dstagecraft.playerStage=PREFIX (a Player/Stage install) is not set: the combined tier needs it");
        }
        Path prefix = Path.of(p).toAbsolutePath();
        assertTrue(Files.isRegularFile(prefix.resolve("env.sh")), prefix + "/env.sh: not a Player/Stage install");
        assertTrue(Files.isExecutable(prefix.resolve("bin/player")), prefix + "/bin/player");
        return prefix;
    }

    /** The variables the install's env.sh exports (as the real-Player tier reads them). */
    private static Map<String, String> playerStageEnv() throws Exception {
        Path sh = playerStagePrefix().resolve("env.sh");
        ProcessBuilder pb = new ProcessBuilder("bash", "-c", ". \"$1\" && env -0", "env", sh.toString());
        pb.environment().clear();
        pb.environment().put("PATH", "/usr/local/bin:/usr/bin:/bin");
        Process p = pb.redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0, "sourcing " + sh + ": " + out);
        Map<String, String> keep = new HashMap<>();
        for (String kv : out.split("\0")) {
            int eq = kv.indexOf('=');
            if (eq > 0 && List.of("PATH", "LD_LIBRARY_PATH", "PLAYERPATH", "STAGEPATH").contains(kv.substring(0, eq))) {
                keep.put(kv.substring(0, eq), kv.substring(eq + 1));
            }
        }
        keep.put("PATH", keep.get("PATH") + File.pathSeparator + System.getenv().getOrDefault("PATH", "/usr/bin:/bin"));
        return keep;
    }

    /** A port free on every address (Player binds 0.0.0.0) and on loopback, for the spy; Player gets another. */
    private static int freePort() throws IOException {
        for (int tries = 0; tries < 200; tries++) {
            int port;
            try (ServerSocket s = new ServerSocket()) {
                s.bind(new InetSocketAddress(InetAddress.getByName("0.0.0.0"), 0));
                port = s.getLocalPort();
            }
            if (isFree(port)) {
                return port;
            }
        }
        throw new AssertionError("no free port");
    }

    private static boolean isFree(int port) {
        for (String host : List.of("0.0.0.0", "127.0.0.1")) {
            try (ServerSocket s = new ServerSocket()) {
                s.setReuseAddress(true);
                s.bind(new InetSocketAddress(InetAddress.getByName(host), port));
            } catch (IOException e) {
                return false;
            }
        }
        return true;
    }

    private static int freeDisplay() {
        for (int n = 100 + (int) (ProcessHandle.current().pid() % 300); n < 1000; n++) {
            if (!Files.exists(Path.of("/tmp/.X11-unix/X" + n)) && !Files.exists(Path.of("/tmp/.X" + n + "-lock"))) {
                return n;
            }
        }
        throw new AssertionError("no free X display number");
    }

    // ------------------------------------------------------------------------------------------ processes

    /** A process this test started (Xvfb, the pose reader), its output collected; close() ends its tree. */
    static final class Proc implements AutoCloseable {
        final Process process;
        final List<String> lines = new CopyOnWriteArrayList<>();
        private final Thread reader;

        Proc(List<String> command, Map<String, String> env) throws IOException {
            ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
            pb.environment().putAll(env);
            process = pb.start();
            reader = Thread.ofVirtual().start(() -> {
                try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                    String l;
                    while ((l = r.readLine()) != null) {
                        lines.add(l);
                    }
                } catch (IOException e) {
                    lines.add("[test] " + e);
                }
            });
        }

        String output() {
            List<String> l = List.copyOf(lines);
            return "\n" + String.join("\n", l.subList(Math.max(0, l.size() - 20), l.size()));
        }

        @Override
        public void close() throws InterruptedException {
            List<ProcessHandle> tree = new ArrayList<>(process.descendants().toList());
            tree.add(process.toHandle());
            tree.forEach(ProcessHandle::destroy);
            for (ProcessHandle h : tree) {
                try {
                    h.onExit().get(5, TimeUnit.SECONDS);
                } catch (Exception e) {
                    h.destroyForcibly();
                }
            }
            process.waitFor(5, TimeUnit.SECONDS);
            reader.join(Duration.ofSeconds(5));
            assertFalse(process.isAlive(), "process " + process.pid() + " ended");
        }
    }

    private Proc start(String name, List<String> command, Map<String, String> env) throws IOException {
        Proc p = new Proc(command, env);
        procs.add(p);
        return p;
    }

    // ------------------------------------------------------------------------------------------ the project

    private static IProject pyDevProjectWithWorlds(String name) throws Exception {
        return WorldsProject.create(name, null, "logs");
    }

    private static IFile write(IProject p, String path, String text) throws Exception {
        Path file = p.getLocation().toPath().resolve(path);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        p.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());
        return p.getFile(path);
    }
}
