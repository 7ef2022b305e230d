package org.stagecraft.tools.session;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.Recorder;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.ToolSpec;
import org.stagecraft.tools.process.ToolState;

/**
 * Whole sessions without Eclipse, with the stand-in Player (a Python script that reads the rewritten
 * cfg itself, listens where it says, and serves a recorded Player conversation).
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotSessionTest {
    private static final Duration WAIT = Duration.ofSeconds(30);
    private static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";

    private final Recorder rec = new Recorder();
    /** Peers block in socket reads: each gets a virtual thread, never the (tiny) common pool. */
    private final ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor();

    @TempDir
    Path tmp;

    @AfterEach
    void end() {
        peers.shutdownNow();
    }

    private SessionConfig config(Path cfg, int defaultPort) {
        return SessionConfig.of(cfg).withDefaultPort(defaultPort)
                .withPlayer(List.of("python3", Worlds.standIn().toString()),
                        Map.of("STANDIN_TRACE", Worlds.traces().resolve(TRACE).toString()))
                .withPlayerRestart(RestartPolicy.NEVER, WAIT).withLog(tmp.resolve("logs/session.mcap"))
                .withScratchRoot(tmp.resolve("scratch"));
    }

    @Test
    void playerOnMovedPortsSpyOnTheOriginalOnesByteExactAndLogged() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        RecordedConnection recorded = RecordedConnection.read(Worlds.traces().resolve(TRACE)).get(0);
        RobotSession session = RobotSession.start(config(Worlds.file("pioneer-laser-sonar.cfg"), port), rec);
        ProcessHandle player;
        int moved;
        Path scratch;
        try {
            assertEquals(List.of(port), List.copyOf(session.portMap().keySet()));
            moved = session.portMap().get(port);
            assertNotEquals(port, moved);
            assertEquals(ToolState.READY, session.player().state());
            player = session.player().process();
            assertTrue(session.player().spec().command().containsAll(List.of("-p", String.valueOf(moved))));
            scratch = session.scratchDirectory();
            assertTrue(session.rewritten().main().startsWith(scratch));
            // the stand-in read the copy on its own and agreed on the port and the paths
            rec.awaitLine(l -> l.text().equals("standin: listening on " + moved), WAIT);
            rec.awaitLine(l -> l.text().endsWith("paths=ok"), WAIT);

            CompletableFuture<ReplayPeer.Result> client = CompletableFuture.supplyAsync(() -> {
                try {
                    return ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), recorded);
                } catch (IOException e) {
                    throw new RuntimeException(e);
                }
            }, peers);
            ReplayPeer.Result r = client.get(60, TimeUnit.SECONDS);
            assertTrue(r.matches(), "the client got Player's recorded bytes; first difference at " + r.firstDifference());
            rec.awaitLine(l -> l.text().equals("standin: served port=" + moved + " bytes_in="
                    + recorded.clientBytes().length + " match=true"), WAIT);
        } finally {
            session.close();
        }
        assertFalse(player.isAlive(), "Player is gone");
        assertEquals(ToolState.STOPPED, session.player().state());
        assertTrue(Ports.isFree("127.0.0.1", port), "the spy's port is free again");
        assertTrue(Ports.isFree("127.0.0.1", moved), "Player's port is free again");
        assertFalse(Files.exists(scratch), "the rewritten cfg is removed");

        try (SpyLogReader log = SpyLogReader.open(tmp.resolve("logs/session.mcap"))) {
            assertFalse(log.recovered(), "the log was closed properly");
            List<LogConnection> conns = log.connections();
            assertEquals(1, conns.size(), "the readiness probe went to Player directly, not through the spy");
            assertEquals(port, conns.get(0).port());
            assertArrayEquals(recorded.clientBytes(), log.streamBytes(conns.get(0).conn(), Direction.CLIENT_TO_SERVER));
            assertArrayEquals(recorded.serverBytes(), log.streamBytes(conns.get(0).conn(), Direction.SERVER_TO_CLIENT));
            assertTrue(log.messageCount() > 100, "decoded messages are logged: " + log.messageCount());
        }
    }

    private CompletableFuture<ReplayPeer.Result> replayClient(int port, RecordedConnection recorded) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                return ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), recorded);
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        }, peers);
    }

    @Test
    void robotsOnSeveralPortsWithAnIncludeAndRelativePaths() throws Exception {
        List<Integer> ports = Ports.free("127.0.0.1", 2);
        int p1 = ports.get(0);
        int p2 = ports.get(1);
        Path proj = Files.createDirectories(tmp.resolve("proj"));
        Files.createDirectories(proj.resolve("worlds"));
        Files.writeString(proj.resolve("worlds/two.world"), "# a world\n");
        Files.writeString(proj.resolve("robots.inc"), "driver ( name \"stage\" provides [ \"%d:position2d:0\" ] model \"r1\" )\n"
                .formatted(p2));
        Path cfg = Files.writeString(proj.resolve("two.cfg"), """
                # two robots, two ports
                driver ( name "stage" provides [ "%1$d:simulation:0" ] plugin "stageplugin" worldfile "worlds/two.world" )
                driver ( name "stage" provides [ "%1$d:position2d:0" ] model "r0" )
                include "robots.inc"
                driver
                (
                  name "rangertolaser"
                  provides [ "localhost:%2$d:laser:0" ]
                  requires [ "%2$d:ranger:1" ]
                )
                """.formatted(p1, p2));
        RecordedConnection recorded = RecordedConnection.read(Worlds.traces().resolve(TRACE)).get(0);
        try (RobotSession session = RobotSession.start(config(cfg, 6665), rec)) {
            assertEquals(List.of(p1, p2), List.copyOf(session.portMap().keySet()));
            int m1 = session.portMap().get(p1);
            int m2 = session.portMap().get(p2);
            rec.awaitLine(l -> l.text().equals("standin: listening on " + m1 + " " + m2), WAIT);
            rec.awaitLine(l -> l.text().endsWith("paths=ok"), WAIT);
            assertEquals(2, session.rewritten().files().size(), "the include was copied too");
            CompletableFuture<ReplayPeer.Result> a = replayClient(p1, recorded);
            CompletableFuture<ReplayPeer.Result> b = replayClient(p2, recorded);
            assertTrue(a.get(60, TimeUnit.SECONDS).matches(), "robot 0 through the spy");
            assertTrue(b.get(60, TimeUnit.SECONDS).matches(), "robot 1 through the spy");
            rec.awaitLine(l -> l.text().startsWith("standin: served port=" + m1 + " ") && l.text().endsWith("match=true"), WAIT);
            rec.awaitLine(l -> l.text().startsWith("standin: served port=" + m2 + " ") && l.text().endsWith("match=true"), WAIT);
        }
        assertTrue(Ports.isFree("127.0.0.1", p1) && Ports.isFree("127.0.0.1", p2));
        try (SpyLogReader log = SpyLogReader.open(tmp.resolve("logs/session.mcap"))) {
            assertEquals(Stream.of(p1, p2).sorted().toList(),
                    log.connections().stream().map(LogConnection::port).sorted().toList());
        }
    }

    @Test
    void aKilledPlayerThatIsNotRestartedFailsTheSession() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        try (RobotSession session = RobotSession.start(config(Worlds.file("pioneer-laser-sonar.cfg"), port), rec)) {
            assertEquals(SessionState.RUNNING, session.state());
            assertFalse(session.failed().isDone());
            ProcessHandle player = session.player().process();
            new ProcessBuilder("kill", "-9", String.valueOf(player.pid())).start().waitFor();

            String reason = session.failed().get(30, TimeUnit.SECONDS);
            assertEquals(SessionState.FAILED, session.state());
            assertTrue(reason.startsWith("Player is gone (exited with exit code 137 (signal 9))"), reason);
            rec.awaitLine(l -> l.tool() == null && l.text().equals("session failed: " + reason), WAIT);
            assertEquals(ToolState.FAILED, session.player().state());
        }
    }

    @Test
    void aClosedSessionHasNotFailed() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        RobotSession session = RobotSession.start(config(Worlds.file("pioneer-laser-sonar.cfg"), port), rec);
        session.close();
        assertEquals(SessionState.CLOSED, session.state());
        assertFalse(session.failed().isDone(), "Player stopped on request is no failure");
    }

    @Test
    void aPlayerCrashIsRestartedOnTheSamePortAndTheSpyGoesOn() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        RecordedConnection recorded = RecordedConnection.read(Worlds.traces().resolve(TRACE)).get(0);
        try (RobotSession session = RobotSession.start(config(Worlds.file("pioneer-laser-sonar.cfg"), port)
                .withPlayerRestart(RestartPolicy.onFailure(1), WAIT), rec)) {
            int moved = session.portMap().get(port);
            long firstPid = session.player().process().pid();
            session.player().write("crash 7\n");
            rec.awaitChange(c -> c.tool().equals("Player") && c.to() == ToolState.READY && c.detail().startsWith("ready again"),
                    WAIT);
            assertEquals(7, session.player().lastExitCode());
            assertEquals(1, session.player().restarts());
            assertNotEquals(firstPid, session.player().process().pid());
            assertTrue(replayClient(port, recorded).get(60, TimeUnit.SECONDS).matches(), "served by the restarted Player");
            rec.awaitLine(l -> l.text().startsWith("standin: served port=" + moved + " ") && l.text().endsWith("match=true"),
                    WAIT);

            session.player().write("crash 9\n");
            assertEquals(ToolState.FAILED, session.player().finished().get(30, TimeUnit.SECONDS));
            assertEquals(9, session.player().lastExitCode());
            assertFalse(session.isClosed(), "a tool that stays down is reported; the session is the user's to end");
        }
    }

    @Test
    void aBadCfgStartsNothingAndNamesFileAndLine() throws Exception {
        Path cfg = Files.writeString(tmp.resolve("bad.cfg"), "driver\n(\n  provides [ \"6665:laser\" ]\n)\n");
        SessionException e = assertThrows(SessionException.class, () -> RobotSession.start(config(cfg, 6665), rec));
        assertTrue(e.getMessage().contains(cfg + ":3: provides: '6665:laser'"), e.getMessage());
        assertTrue(rec.lines.isEmpty(), "no tool was started: " + rec.lines);
        assertFalse(Files.exists(tmp.resolve("scratch")) && Files.list(tmp.resolve("scratch")).findAny().isPresent());
    }

    @Test
    void aPortInUseIsNamedWithWhereItComesFrom() throws Exception {
        try (ServerSocket busy = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            int port = busy.getLocalPort();
            SessionException e = assertThrows(SessionException.class,
                    () -> RobotSession.start(config(Worlds.file("pioneer-laser-sonar.cfg"), port), rec));
            assertTrue(e.getMessage().startsWith("port " + port + " is already in use on 127.0.0.1"), e.getMessage());
            assertTrue(e.getMessage().contains("the default port (-p " + port + ") of \"simulation:0\" at "
                    + Worlds.file("pioneer-laser-sonar.cfg").toAbsolutePath().normalize() + ":6"), e.getMessage());
            assertTrue(rec.lines.isEmpty(), "nothing was started: " + rec.lines);
        }
    }

    @Test
    void aMissingPlayerStopsTheToolsAlreadyStarted() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        ToolSpec helper = ToolSpec.of("helper", List.of("sh", "-c", "echo helper up; exec sleep 300"))
                .withReadiness(Readiness.line("helper up"), WAIT);
        SessionConfig c = config(Worlds.file("pioneer-laser-sonar.cfg"), port)
                .withPlayer(List.of("/nonexistent/stagecraft/player"), Map.of()).withTools(List.of(helper));
        SessionException e = assertThrows(SessionException.class, () -> RobotSession.start(c, rec));
        assertTrue(e.getMessage().contains("tool 'Player': cannot run '/nonexistent/stagecraft/player': no such file"),
                e.getMessage());
        assertTrue(rec.states("helper").contains(ToolState.READY), "the helper had started");
        assertEquals(ToolState.STOPPED, rec.states("helper").get(rec.states("helper").size() - 1), "and was stopped");
        long helperPid = Long.parseLong(rec.awaitLine(l -> l.text().startsWith("started sh"), WAIT).text()
                .replaceAll(".*\\(pid (\\d+)\\)$", "$1"));
        assertFalse(ProcessHandle.of(helperPid).map(ProcessHandle::isAlive).orElse(false), "helper process is gone");
        assertTrue(Ports.isFree("127.0.0.1", port));
        try (Stream<Path> left = Files.list(tmp.resolve("scratch"))) {
            assertEquals(0, left.count(), "the scratch directory was removed");
        }
    }

    @Test
    void staleScratchDirectoriesOfDeadOwnersAreRemovedOnTheNextStart() throws Exception {
        Process p = new ProcessBuilder("true").start();
        p.waitFor();
        Path root = tmp.resolve("scratch");
        Path stale = Files.createDirectories(root.resolve(p.pid() + "-1-abc"));
        Files.writeString(stale.resolve("pioneer.cfg"), "left over");
        Path live = Files.createDirectories(root.resolve(ProcessHandle.current().pid() + "-99-live"));
        Path foreign = Files.createDirectories(root.resolve("not-ours"));
        try (ScratchDirectory s = ScratchDirectory.create(root)) {
            assertFalse(Files.exists(stale), "a crashed owner's files are removed");
            assertTrue(Files.exists(live), "a running owner's files are kept");
            assertTrue(Files.exists(foreign));
            assertTrue(Files.isDirectory(s.path()));
            assertTrue(s.path().getFileName().toString().startsWith(ProcessHandle.current().pid() + "-"));
        }
    }
}
