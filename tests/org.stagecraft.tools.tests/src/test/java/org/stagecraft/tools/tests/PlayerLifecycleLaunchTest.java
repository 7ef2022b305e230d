package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.core.model.IProcess;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.session.SessionState;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionParts;
import org.stagecraft.tools.ui.prefs.ToolPreferences;
import org.stagecraft.tools.ui.view.ToolsModel;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Player's life in a launched Robot Session, with a stand-in Player that logs every connection:
 * the readiness check is one clean client (banner read, orderly close), and a Player killed with
 * SIGKILL fails the session everywhere a user looks.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
@LogsErrors({ "Player failed: exited with exit code 137", "Player is gone \\(exited with exit code 137" })
class PlayerLifecycleLaunchTest {
    private static final Duration WAIT = Duration.ofSeconds(30);
    private static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";
    private final List<ILaunch> launches = new ArrayList<>();
    private Path tmp;
    private Path connectionLog;
    private IProject project;

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-player-life");
        connectionLog = tmp.resolve("connections.jsonl");
        project = Fixtures.projectWithWorlds("player-life-" + System.nanoTime());
        ToolPreferences.setTools(List.of());
    }

    @AfterEach
    void tearDown() throws Exception {
        Fixtures.terminateAll(launches, WAIT);
        project.delete(true, true, new NullProgressMonitor());
    }

    private ILaunch launch() throws Exception {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("player-life"));
        wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/pioneer-laser-sonar.cfg").getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, Fixtures.standIn(tmp).toString());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_TRACE", Fixtures.traces().resolve(TRACE).toString(),
                "STANDIN_CONNECTION_LOG", connectionLog.toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, Ports.free("127.0.0.1", 1).get(0));
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        ILaunch l = wc.launch(ILaunchManager.RUN_MODE, new NullProgressMonitor());
        launches.add(l);
        return l;
    }

    private List<JsonObject> connections() {
        try {
            if (!Files.exists(connectionLog)) {
                return List.of();
            }
            return Files.readAllLines(connectionLog).stream().filter(s -> !s.isBlank())
                    .map(s -> JsonParser.parseString(s).getAsJsonObject()).toList();
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void theReadinessCheckIsOneCleanClientOfPlayer() throws Exception {
        ILaunch launch = launch();
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
        assertNotNull(parts, "the session runs");
        int moved = parts.session().portMap().values().iterator().next();
        Await.until("the stand-in logged the probe's connection", WAIT, () -> !connections().isEmpty(), () -> String.valueOf(connections()));
        List<JsonObject> seen = connections();
        assertEquals(1, seen.size(), "one probe connection: " + seen);
        JsonObject probe = seen.get(0);
        assertEquals(moved, probe.get("port").getAsInt());
        assertEquals("sent", probe.get("banner").getAsString(), "Player's ident string went out (no 'failed to send ident string')");
        assertEquals("eof", probe.get("end").getAsString(), "closed in order, no reset (no 'other error on client')");
        assertEquals(0, probe.get("bytes_in").getAsInt());
    }

    @Test
    void aKilledPlayerFailsTheSessionItsLaunchAndItsRowInTheToolsView() throws Exception {
        ILaunch launch = launch();
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
        assertNotNull(parts, "the session runs");
        RobotSession session = parts.session();
        assertEquals(SessionState.RUNNING, session.state());
        assertEquals(ToolState.READY, ToolsModel.get().find(parts.sessionName(), SessionParts.SESSION_PART).state());
        long pid = session.player().process().pid();

        new ProcessBuilder("kill", "-9", String.valueOf(pid)).start().waitFor();

        Await.until("the session is failed", WAIT, () -> session.state() == SessionState.FAILED, () -> String.valueOf(session.state()));
        Await.until("the Tools view shows the session failed", WAIT, () -> {
            ToolsModel.Row r = ToolsModel.get().find(parts.sessionName(), SessionParts.SESSION_PART);
            return r != null && r.state() == ToolState.FAILED;
        }, () -> String.valueOf(ToolsModel.get().rows()));
        assertTrue(ToolsModel.get().find(parts.sessionName(), SessionParts.SESSION_PART).detail().startsWith("Player is gone"));
        assertEquals(ToolState.FAILED, ToolsModel.get().find(parts.sessionName(), RobotSession.PLAYER_TOOL_NAME).state());
        Await.until("the launch has ended", WAIT, launch::isTerminated,
                () -> Arrays.toString(Arrays.stream(launch.getProcesses()).map(p -> p.getLabel() + ":" + p.isTerminated()).toArray()));
        for (IProcess p : launch.getProcesses()) {
            assertNotEquals(0, p.getExitValue(), p.getLabel() + " ended as failed");
        }
        assertTrue(parts.failure().startsWith("Player is gone"), parts.failure());
    }
}
