package org.stagecraft.demo.recorded;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.play.RecordedRobot;
import org.stagecraft.recording.play.TimedConnection;
import org.stagecraft.recording.play.TimedRecording;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.session.SessionConfig;

/**
 * The demo's pipeline without Eclipse: a Robot Session on the shipped cfg whose "Player" is the
 * recorded Player program (its own JVM, started by the session like Player: {@code -p MOVED copy.cfg}),
 * the recorded robot program on the other side of the spy.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RecordedSessionTest {
    private static final Duration WAIT = Duration.ofSeconds(30);

    @TempDir
    Path tmp;

    private static List<String> javaCommand(Class<?> main) {
        return List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), main.getName());
    }

    @Test
    void theRecordedPlayerServesTheRecordedRobotThroughTheSpyAndTheLogHasEveryByte() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        double speed = 8;
        Lines lines = new Lines();
        SessionConfig config = SessionConfig.of(DemoFiles.cfg()).withDefaultPort(port)
                .withPlayer(javaCommand(RecordedPlayerMain.class), Map.of(Options.RECORDING_VARIABLE,
                        DemoFiles.recording().toString(), Options.SPEED_VARIABLE, String.valueOf(speed)))
                .withPlayerRestart(RestartPolicy.NEVER, WAIT).withLog(tmp.resolve("spy-logs/demo.mcap"))
                .withScratchRoot(tmp.resolve("scratch"));
        TimedRecording recording = TimedRecording.read(DemoFiles.recording());
        TimedConnection conn = recording.connections().get(0);
        ProcessHandle player;
        try (RobotSession session = RobotSession.start(config, lines)) {
            int moved = session.portMap().get(port);
            player = session.player().process();
            assertEquals(ToolState.READY, session.player().state());
            lines.await(l -> l.startsWith("Player: recorded Player: serving ") && l.endsWith("on [127.0.0.1:" + moved + "]"),
                    WAIT);

            List<RecordedRobot.Pass> passes = new ArrayList<>();
            new RecordedRobot(recording, new InetSocketAddress("127.0.0.1", port), speed, passes::add).run(1, WAIT);
            assertTrue(passes.get(0).result().matches(), passes.get(0).describe());
            lines.await(l -> l.equals("Player: recorded Player: served recorded connection 1 on port " + moved + ": sent "
                    + conn.serverBytes().length + " bytes, received " + conn.clientBytes().length
                    + " bytes, exactly what the recorded robot program sent"), WAIT);
        }
        assertFalse(player.isAlive(), "the recorded Player stops with the session");
        try (SpyLogReader log = SpyLogReader.open(tmp.resolve("spy-logs/demo.mcap"))) {
            assertFalse(log.recovered());
            List<LogConnection> conns = log.connections();
            assertEquals(1, conns.size());
            assertArrayEquals(conn.clientBytes(), log.streamBytes(conns.get(0).conn(), Direction.CLIENT_TO_SERVER));
            assertArrayEquals(conn.serverBytes(), log.streamBytes(conns.get(0).conn(), Direction.SERVER_TO_CLIENT));
        }
    }

    @Test
    void aCorruptRecordingFailsTheSessionWithItsReason() throws Exception {
        Path bad = java.nio.file.Files.writeString(tmp.resolve("bad.trace.jsonl"), "not json\n");
        int port = Ports.free("127.0.0.1", 1).get(0);
        Lines lines = new Lines();
        SessionConfig config = SessionConfig.of(DemoFiles.cfg()).withDefaultPort(port)
                .withPlayer(javaCommand(RecordedPlayerMain.class), Map.of(Options.RECORDING_VARIABLE, bad.toString()))
                .withPlayerRestart(RestartPolicy.NEVER, WAIT).withScratchRoot(tmp.resolve("scratch"));
        org.stagecraft.tools.session.SessionException e = org.junit.jupiter.api.Assertions.assertThrows(
                org.stagecraft.tools.session.SessionException.class, () -> RobotSession.start(config, lines));
        assertTrue(e.getMessage().contains("recorded Player: the recording is corrupt: " + bad + ":1: not valid JSON"),
                e.getMessage());
        assertTrue(Ports.isFree("127.0.0.1", port));
    }
}
