package org.stagecraft.player.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.DataInputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.SupervisedTool;
import org.stagecraft.tools.process.ToolListener;
import org.stagecraft.tools.process.ToolSpec;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.session.SessionConfig;

/**
 * The real-Player tier: Robot Sessions (the same {@link SessionConfig} a Robot Session launch builds:
 * Player program, default port, Player's environment, restart policy, readiness time, spy log) on
 * the shipped worlds with a real Player 3.1.1-dev and Stage 4.3.0 running headless, and real robot
 * programs driving the simulated robots through the spy.
 *
 * <p>Player binds 0.0.0.0 (it has no option to bind an address), so the tests choose ports that are
 * free on every address; each test closes its session and checks that no process and no port is left.
 */
@Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RealPlayerSessionTest {
    private static final Duration WAIT = Duration.ofSeconds(60);
    private static final String BANNER = "Player v.3.1.1-dev";

    @TempDir
    Path tmp;

    /** Everything the session's tools said (Player's console), as the launch's consoles show it. */
    private final SessionConsole listener = new SessionConsole();
    private final List<String> console = listener.lines;
    private final List<PlayerStage.Program> programs = new ArrayList<>();
    private RobotSession session;


    @AfterEach
    void stopEverything() throws Exception {
        for (PlayerStage.Program p : programs) {
            p.close();
        }
        if (session != null) {
            session.close();
        }
    }

    /** As SessionSettings.read does for a launch: Player program, its environment, default port, restart, readiness, log. */
    private SessionConfig config(Path cfg, int defaultPort) {
        return SessionConfig.of(cfg).withPlayer(List.of(PlayerStage.player().toString()), PlayerStage.env())
                .withDefaultPort(defaultPort).withPlayerRestart(RestartPolicy.NEVER, Duration.ofSeconds(30)).withTools(List.of())
                .withLog(tmp.resolve("spy-logs/session.mcap")).withScratchRoot(tmp.resolve("scratch"));
    }

    private RobotSession start(SessionConfig c) throws Exception {
        for (int port : List.of(c.defaultPort())) {
            assertTrue(PlayerStage.isFree(port), "port " + port + " is free before the session");
        }
        session = RobotSession.start(c, listener);
        return session;
    }

    /** Closes the session and checks that nothing of it is left: no process, no port, no scratch files. */
    private void closeAndCheckClean() throws Exception {
        ProcessHandle player = session.player().process();
        List<ProcessHandle> tree = new ArrayList<>(player.descendants().toList());
        tree.add(player);
        for (SupervisedTool t : session.tools()) {
            tree.addAll(t.process().descendants().toList());
            tree.add(t.process());
        }
        Map<Integer, Integer> ports = session.portMap();
        Path scratch = session.scratchDirectory();
        for (PlayerStage.Program p : programs) {
            p.close();
        }
        programs.clear();
        session.close();
        for (ProcessHandle h : tree) {
            assertFalse(h.isAlive(), "process " + h.pid() + " of Player's or a tool's tree is gone");
        }
        for (SupervisedTool t : session.tools()) {
            assertEquals(ToolState.STOPPED, t.state(), "the session's tool " + t.name() + " is stopped");
        }
        assertEquals(ToolState.STOPPED, session.player().state());
        for (Map.Entry<Integer, Integer> e : ports.entrySet()) {
            assertTrue(PlayerStage.await(Duration.ofSeconds(10), () -> PlayerStage.isFree(e.getKey())),
                    "the spy's port " + e.getKey() + " is free again");
            assertTrue(PlayerStage.await(Duration.ofSeconds(10), () -> PlayerStage.isFree(e.getValue())),
                    "Player's moved port " + e.getValue() + " is free again (on every address)");
        }
        assertFalse(Files.exists(scratch), "the rewritten cfg's scratch directory is removed");
    }

    private PlayerStage.Program python(String name, Path script, List<String> args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(PlayerStage.python(), "-u", script.toString()));
        cmd.addAll(args);
        Map<String, String> env = new HashMap<>();
        env.put("PYTHONPATH", PlayerStage.pythonClient().resolve("src").toString());
        PlayerStage.Program p = new PlayerStage.Program(name, cmd, env, null);
        programs.add(p);
        return p;
    }

    private static String banner(int port) throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            s.setSoTimeout(10_000);
            byte[] b = new byte[32];
            new DataInputStream(s.getInputStream()).readFully(b);
            return new String(b, StandardCharsets.US_ASCII).replace("\0", "");
        }
    }

    // ------------------------------------------------------------------------------------------------

    @Test
    void robotSessionOnTheHeadlessWorld() throws Exception {
        int port = PlayerStage.freePorts(1).get(0);
        Path cfg = PlayerStage.worlds().resolve("pioneer-laser-sonar-headless.cfg");
        start(config(cfg, port));

        // ports moved: the spy has the original port, Player a new one
        assertEquals(List.of(port), List.copyOf(session.portMap().keySet()));
        int moved = session.portMap().get(port);
        assertNotEquals(port, moved);
        assertEquals(ToolState.READY, session.player().state(), "Player is ready (its moved port accepts connections)");
        List<String> cmd = session.player().spec().command();
        assertEquals(PlayerStage.player().toString(), cmd.get(0));
        assertEquals(List.of("-p", String.valueOf(moved), session.rewritten().main().toString()),
                cmd.subList(cmd.size() - 3, cmd.size()));
        String copy = Files.readString(session.rewritten().main());
        assertTrue(copy.contains("usegui 0"), "the copy is the headless cfg");
        assertTrue(copy.contains(PlayerStage.worlds().resolve("pioneer-laser-sonar.world").toString()),
                "the world file is made absolute in the copy: " + copy);
        assertFalse(PlayerStage.isFree(moved), "Player listens on its moved port");
        assertFalse(PlayerStage.isFree(port), "the spy listens on the original port");

        // Player answers on the moved port directly, and through the spy on the original one
        assertEquals(BANNER, banner(moved));
        assertEquals(BANNER, banner(port));
        // a robot program through the spy: data flows both ways
        PlayerStage.Program drive = python("drive", PlayerStage.script("drive.py"),
                List.of("--port", String.valueOf(port), "--speed", "0", "--turn", "0", "--rounds", "20"));
        assertEquals(0, drive.awaitExit(WAIT), drive.output());
        assertTrue(drive.anyLine(l -> l.equals("drive: port " + port + " done")), drive.output());

        long pid = session.player().process().pid();
        closeAndCheckClean();

        // Player's console output reached the session (stdout is block-buffered into a pipe: it is flushed
        // when Player exits on the session's SIGTERM)
        assertTrue(console.stream().anyMatch(l -> l.startsWith("Player|SUPERVISOR|") && l.contains(String.valueOf(pid))),
                "the session noted Player's start with its pid: " + console);
        assertTrue(console.stream().anyMatch(l -> l.startsWith("Player|STDOUT|") || l.startsWith("Player|STDERR|")),
                "Player's own output was captured: " + console);
        assertTrue(console.stream().anyMatch(l -> l.startsWith("Player|") && l.contains("Listening on ports")
                && l.contains(String.valueOf(moved))), "Player said it listens on the moved port: " + console);

        // the spy log: complete, the connections on the original port, the banner and decoded traffic
        SpyLog log = SpyLog.read(tmp.resolve("spy-logs/session.mcap"));
        assertFalse(log.recovered, "the spy log was closed properly");
        assertEquals(2, log.connections.size(), "the banner check and drive.py through the spy (the direct one is not "
                + "spied): " + log.connections);
        for (LogConnection c : log.connections) {
            assertEquals(port, c.port(), "programs connected to the original port");
            assertTrue(c.upstream().endsWith(":" + moved), "the spy relayed to Player's moved port: " + c.upstream());
        }
        assertEquals(0, log.decodeProblems, "every message decodes");
        for (LogConnection c : log.connections) {
            assertEquals(BANNER, log.banners.get(c.conn()), "Player's ident is logged for connection " + c.conn());
        }
        int driveConn = log.connections.get(1).conn();
        assertTrue(log.states(driveConn).size() >= 10, "position2d data through the spy");
        assertTrue(log.commands(driveConn).size() >= 10, "drive.py's commands through the spy");
    }

    @Test
    void laserObstacleAvoidDrivesTheRobotThroughTheSpy() throws Exception {
        Path example = PlayerStage.prefix().resolve("share/player/examples/bin/laserobstacleavoid");
        assertTrue(Files.isExecutable(example), example + " was built and installed by player-stage.sh");
        int port = PlayerStage.freePorts(1).get(0);
        start(config(PlayerStage.worlds().resolve("pioneer-laser-sonar-headless.cfg"), port));
        Map<String, String> env = new HashMap<>(PlayerStage.env());
        PlayerStage.Program avoid = new PlayerStage.Program("laserobstacleavoid",
                List.of(example.toString(), "-h", "127.0.0.1", "-p", String.valueOf(port)), env, null);
        programs.add(avoid);
        // one "speed:" line per control cycle (std::endl flushes the pipe); headless Stage runs ahead of the
        // example, so 400 cycles are far more than 40 s of simulated time
        assertTrue(PlayerStage.await(Duration.ofSeconds(120), () -> avoid.count(l -> l.startsWith("speed:")) >= 400
                || !avoid.process.isAlive()), "laserobstacleavoid ran 400 control cycles: " + avoid.output());
        assertTrue(avoid.process.isAlive(), "laserobstacleavoid still runs: " + avoid.output());
        closeAndCheckClean();

        SpyLog log = SpyLog.read(tmp.resolve("spy-logs/session.mcap"));
        assertEquals(1, log.connections.size());
        int conn = log.connections.get(0).conn();
        List<Position2d.State> states = log.states(conn);
        List<Position2d.CmdVel> cmds = log.commands(conn);
        assertTrue(cmds.size() >= 300, "the example sent its commands through the spy: " + cmds.size());
        assertTrue(cmds.stream().anyMatch(c -> c.vel().px() > 0), "it drove forward");
        assertTrue(cmds.stream().anyMatch(c -> c.vel().pa() != 0), "it turned");
        Pose2d first = states.get(0).pos();
        double path = 0;
        for (int i = 1; i < states.size(); i++) {
            path += SpyLog.distance(states.get(i - 1).pos(), states.get(i).pos());
        }
        assertTrue(path > 2.0, "the robot travelled " + path + " m from " + first);
        System.out.println("laserobstacleavoid: " + cmds.size() + " commands, " + String.format("%.2f", path) + " m travelled");
        assertTrue(states.stream().allMatch(s -> s.stall() == 0), "and never ran into anything (stall stayed 0)");
    }

    /**
     * The Sentinel is a smooth controller written for a robot in real time. Headless Stage runs ~10-18x
     * faster than real time, so each of its control rounds would see the world jump by a large angle and
     * it hunts; so this test runs Stage as users watch it: with its window (pioneer-laser-sonar.cfg,
     * usegui 1) on a private Xvfb display that the session starts as a user tool, in real time.
     */
    @Test
    void laserSentinelTurnsOnTheSpotToTheNearestReturnAndStops() throws Exception {
        int port = PlayerStage.freePorts(1).get(0);
        int display = PlayerStage.freeDisplay();
        ToolSpec xvfb = PlayerStage.xvfb(display);
        Map<String, String> env = new HashMap<>(PlayerStage.env());
        env.put("DISPLAY", ":" + display);
        SessionConfig withWindow = config(PlayerStage.worlds().resolve("pioneer-laser-sonar.cfg"), port).withTools(List.of(xvfb));
        start(withWindow.withPlayer(withWindow.playerCommand(), env));
        assertEquals(ToolState.READY, session.tools().get(0).state(), "Xvfb started as the session's tool, before Player");
        PlayerStage.Program sentinel = python("laser_sentinel.py",
                PlayerStage.pythonClient().resolve("examples/laser_sentinel.py"),
                List.of("--host", "127.0.0.1", "--port", String.valueOf(port), "--rounds", "200"));
        assertEquals(0, sentinel.awaitExit(Duration.ofSeconds(180)), sentinel.output());
        assertTrue(sentinel.anyLine(l -> l.startsWith("laser sentinel: watching laser:0")), sentinel.output());
        closeAndCheckClean();

        SpyLog log = SpyLog.read(tmp.resolve("spy-logs/session.mcap"));
        int conn = log.connections.get(0).conn();
        List<Position2d.State> states = log.states(conn);
        List<Position2d.CmdVel> cmds = log.commands(conn);
        assertTrue(states.size() > 50, "poses through the spy: " + states.size());
        Pose2d first = states.get(0).pos();
        Pose2d last = states.get(states.size() - 1).pos();
        double turned = Math.toDegrees(Math.abs(SpyLog.angleDiff(last.pa(), first.pa())));
        assertTrue(turned > 10, "the sentinel turned: " + turned + " degrees from " + first + " to " + last);
        for (Position2d.State s : states) {
            assertTrue(SpyLog.distance(first, s.pos()) < 0.05, "it turns on the spot, never drives: " + s.pos());
        }
        assertTrue(cmds.stream().allMatch(c -> c.vel().px() == 0 && c.vel().py() == 0), "no forward speed is ever commanded");
        // at the end it faces the nearest return and has stopped
        List<Position2d.CmdVel> tail = cmds.subList(Math.max(0, cmds.size() - 20), cmds.size());
        assertTrue(tail.stream().allMatch(c -> c.vel().pa() == 0), "the last commands stop the turn: " + tail);
        Pose2d before = states.get(Math.max(0, states.size() - 10)).pos();
        assertTrue(Math.toDegrees(Math.abs(SpyLog.angleDiff(last.pa(), before.pa()))) < 0.5, "the robot stands still at the end");
        SpyLog.Msg lastScan = null;
        for (SpyLog.Msg m : log.of(conn)) {
            if (m.dir() == Direction.SERVER_TO_CLIENT && m.is(SpyLog.LASER, 0, SpyLog.DATA, 1)) {
                lastScan = m;
            }
        }
        assertTrue(lastScan != null, "laser scans through the spy");
        Laser.Scan scan = SpyLog.scan(lastScan);
        int nearest = -1;
        for (int i = 0; i < scan.rangesCount(); i++) {
            float r = scan.ranges().get(i);
            if (r > 0 && r < Math.min(3.0, scan.maxRange()) && (nearest < 0 || r < scan.ranges().get(nearest))) {
                nearest = i;
            }
        }
        assertTrue(nearest >= 0, "something is within 3 m in the last scan");
        double bearing = Math.toDegrees(scan.minAngle() + nearest * scan.resolution());
        assertTrue(Math.abs(bearing) <= 3.0, "the nearest return is (almost) straight ahead at the end: " + bearing + " deg");
        System.out.println("laser sentinel: turned " + String.format("%.1f", turned) + " deg on the spot, nearest return at "
                + String.format("%.1f", bearing) + " deg, " + String.format("%.2f", scan.ranges().get(nearest)) + " m");
    }

    @Test
    void sundayStrollTravelsAndNeverDrivesOnWithTheFrontSonarUnderItsClearance() throws Exception {
        int port = PlayerStage.freePorts(1).get(0);
        start(config(PlayerStage.worlds().resolve("pioneer-laser-sonar-headless.cfg"), port));
        PlayerStage.Program stroll = python("sunday_stroll.py",
                PlayerStage.pythonClient().resolve("examples/sunday_stroll.py"),
                List.of("--host", "127.0.0.1", "--port", String.valueOf(port), "--seed", "7", "--rounds", "600"));
        assertEquals(0, stroll.awaitExit(Duration.ofSeconds(180)), stroll.output());
        assertTrue(stroll.anyLine(l -> l.startsWith("sunday stroll: ranger:0")), stroll.output());
        closeAndCheckClean();

        SpyLog log = SpyLog.read(tmp.resolve("spy-logs/session.mcap"));
        int conn = log.connections.get(0).conn();
        // which way each sonar looks: from the GET_GEOM reply the program asked for
        Ranger.Geom geom = log.of(conn).stream()
                .filter(m -> m.dir() == Direction.SERVER_TO_CLIENT && m.is(SpyLog.RANGER, 0, SpyLog.RESP_ACK, 1))
                .map(SpyLog::rangerGeom).findFirst().orElseThrow(() -> new AssertionError("no sonar geometry reply"));
        List<Pose3d> poses = geom.elementPoses();
        assertEquals(16, poses.size(), "the Pioneer's 16 sonars");
        double clearance = 0.6;
        // PULL mode: the program asks for a round of data (REQ DATA), gets it up to a SYNCH, decides and
        // sends its command. Each direction's order in the log is exact, but the two directions are
        // observed by two relay threads; so rounds are matched by count, not by interleaving: the command
        // after the k-th REQ DATA was decided on the sonar data as of the k-th SYNCH.
        List<double[]> rangesAtSynch = new ArrayList<>();
        double[] latest = null;
        List<Pose2d> path = new ArrayList<>();
        for (SpyLog.Msg m : log.of(conn)) {
            if (m.dir() != Direction.SERVER_TO_CLIENT) {
                continue;
            }
            if (m.is(SpyLog.RANGER, 0, SpyLog.DATA, 1)) {
                latest = SpyLog.ranges(m).values().toArray();
            } else if (m.is(SpyLog.POSITION2D, 0, SpyLog.DATA, 1)) {
                path.add(((Position2d.State) m.decoded().body()).pos());
            } else if (m.header().type() == SpyLog.SYNCH) {
                rangesAtSynch.add(latest);
            }
        }
        int rounds = 0;
        int forward = 0;
        int stoppedForObstacle = 0;
        for (SpyLog.Msg m : log.of(conn)) {
            if (m.dir() != Direction.CLIENT_TO_SERVER) {
                continue;
            }
            if (m.is(SpyLog.PLAYER, 0, SpyLog.REQ, SpyLog.REQ_DATA)) {
                rounds++;
            } else if (m.is(SpyLog.POSITION2D, 0, SpyLog.CMD, 1) && rounds > 0) {
                Position2d.CmdVel c = (Position2d.CmdVel) m.decoded().body();
                assertTrue(rounds <= rangesAtSynch.size(), "round " + rounds + " ended with a SYNCH");
                double[] seen = rangesAtSynch.get(rounds - 1);
                if (seen == null) {
                    continue;
                }
                double front = Double.POSITIVE_INFINITY;
                for (int i = 0; i < poses.size() && i < seen.length; i++) {
                    if (Math.abs(SpyLog.angleDiff(poses.get(i).pyaw(), 0)) <= Math.toRadians(60)) {
                        front = Math.min(front, seen[i]);
                    }
                }
                if (c.vel().px() > 0) {
                    forward++;
                    assertTrue(front >= clearance, "round " + rounds + ": drove on (" + c.vel().px()
                            + " m/s) with the front sonar at " + front + " m, under the clearance of " + clearance
                            + " m; sonar ranges " + java.util.Arrays.toString(seen));
                } else if (front < clearance) {
                    stoppedForObstacle++;
                }
            }
        }
        assertTrue(rounds > 100, "rounds of data: " + rounds);
        assertTrue(forward > 100, "it strolled: " + forward + " forward commands");
        double travelled = 0;
        for (int i = 1; i < path.size(); i++) {
            travelled += SpyLog.distance(path.get(i - 1), path.get(i));
        }
        assertTrue(travelled > 2.0, "the robot travelled " + travelled + " m");
        System.out.println("sunday stroll: " + forward + " forward commands, " + stoppedForObstacle
                + " commands standing before an obstacle, " + String.format("%.2f", travelled) + " m travelled");
    }

    @Test
    void sixRobotsOnSixPortsAllMove() throws Exception {
        List<Integer> ports = PlayerStage.freePorts(6);
        // six-robots.cfg made headless in a copy, on six free ports instead of 7665..7670, world file absolute
        String text = Files.readString(PlayerStage.worlds().resolve("six-robots.cfg"));
        String copy = text.replace("usegui 1", "usegui 0").replace("worldfile \"six-robots.world\"",
                "worldfile \"" + PlayerStage.worlds().resolve("six-robots.world") + "\"");
        for (int i = 0; i < 6; i++) {
            copy = copy.replace("\"" + (7665 + i) + ":", "\"" + ports.get(i) + ":");
        }
        assertFalse(copy.contains("\"7665:"), "every port was replaced");
        Path cfg = Files.writeString(tmp.resolve("six-robots-headless.cfg"), copy);
        start(config(cfg, PlayerStage.freePorts(1).get(0)));
        assertEquals(ports.stream().sorted().toList(), session.portMap().keySet().stream().sorted().toList(),
                "the spy has the six original ports");
        assertTrue(session.portMap().values().stream().distinct().count() == 6
                && session.portMap().values().stream().noneMatch(ports::contains), "Player has six other ports");

        List<PlayerStage.Program> drivers = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            drivers.add(python("drive-" + i, PlayerStage.script("drive.py"), List.of("--port", String.valueOf(ports.get(i)),
                    "--speed", "0.2", "--turn", String.valueOf(i % 2 == 0 ? 0.3 : -0.3), "--distance", "0.5", "--rounds", "20000")));
        }
        for (PlayerStage.Program d : drivers) {
            assertEquals(0, d.awaitExit(Duration.ofSeconds(120)), d.name + ": " + d.output());
        }
        closeAndCheckClean();

        SpyLog log = SpyLog.read(tmp.resolve("spy-logs/session.mcap"));
        Map<Integer, Integer> byPort = log.connByPort();
        assertEquals(ports.stream().sorted().toList(), byPort.keySet().stream().sorted().toList(), "one connection per robot port");
        List<Pose2d> starts = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            List<Position2d.State> states = log.states(byPort.get(ports.get(i)));
            assertTrue(states.size() > 20, "robot " + i + " reported poses: " + states.size());
            Pose2d a = states.get(0).pos();
            Pose2d b = states.get(states.size() - 1).pos();
            assertTrue(SpyLog.distance(a, b) > 0.4, "robot " + i + " moved: " + a + " -> " + b);
            double turned = SpyLog.angleDiff(b.pa(), a.pa());
            assertTrue(i % 2 == 0 ? turned > 0 : turned < 0, "robot " + i + " turned the way it was told: " + turned);
            starts.add(a);
        }
        assertEquals(6, starts.stream().map(p -> Math.round(p.px() * 10) + "," + Math.round(p.py() * 10)).distinct().count(),
                "six different robots (six start poses): " + starts);
    }

    @Test
    void libplayercPythonBindingsReadTheSameThroughTheSpyAsDirectly() throws Exception {
        Map<String, String> env = PlayerStage.env();
        if (!env.containsKey("PYTHONPATH")) {
            fail("libplayerc's Python bindings were not built into " + PlayerStage.prefix() + " (no PYTHONPATH in env.sh)");
        }
        int port = PlayerStage.freePorts(1).get(0);
        start(config(PlayerStage.worlds().resolve("pioneer-laser-sonar-headless.cfg"), port));
        int moved = session.portMap().get(port);
        String py = env.getOrDefault("STAGECRAFT_PLAYERC_PYTHON", "/usr/bin/python3");
        String viaSpy = readWithPlayerc(py, env, port);
        String direct = readWithPlayerc(py, env, moved);
        com.google.gson.JsonObject read = com.google.gson.JsonParser.parseString(viaSpy).getAsJsonObject();
        assertTrue(read.get("laser_count").getAsInt() > 100, "libplayerc read a laser scan: " + viaSpy);
        assertEquals(16, read.get("sonar_count").getAsInt(), "and the 16 sonars: " + viaSpy);
        // nobody drives: the simulated world is still, so the values are the same, bit for bit
        assertEquals(direct, viaSpy, "libplayerc reads the same values through the spy as from Player directly");
        closeAndCheckClean();

        // and the project's decoder read the same laser ranges from the spy log as libplayerc did
        SpyLog log = SpyLog.read(tmp.resolve("spy-logs/session.mcap"));
        assertEquals(1, log.connections.size(), "only the spied connection is in the log");
        SpyLog.Msg scanMsg = null;
        for (SpyLog.Msg m : log.of(log.connections.get(0).conn())) {
            if (m.dir() == Direction.SERVER_TO_CLIENT && m.is(SpyLog.LASER, 0, SpyLog.DATA, 1)) {
                scanMsg = m;
            }
        }
        assertTrue(scanMsg != null, "laser data through the spy");
        Laser.Scan scan = SpyLog.scan(scanMsg);
        com.google.gson.JsonObject o = com.google.gson.JsonParser.parseString(viaSpy).getAsJsonObject();
        com.google.gson.JsonArray ranges = o.getAsJsonArray("laser_ranges");
        assertEquals(scan.rangesCount(), ranges.size());
        for (int i = 0; i < ranges.size(); i++) {
            assertEquals((double) scan.ranges().get(i), ranges.get(i).getAsDouble(), 0.0, "laser range " + i);
        }
    }

    private String readWithPlayerc(String py, Map<String, String> env, int port) throws Exception {
        PlayerStage.Program p = new PlayerStage.Program("playerc_read.py:" + port,
                List.of(py, PlayerStage.script("playerc_read.py").toString(), "127.0.0.1", String.valueOf(port)), env, null);
        programs.add(p);
        assertEquals(0, p.awaitExit(WAIT), p.output());
        return p.lines.stream().filter(l -> l.startsWith("{")).findFirst()
                .orElseThrow(() -> new AssertionError("no JSON from libplayerc: " + p.output()));
    }
}
