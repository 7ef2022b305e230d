package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.ILogListener;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.osgi.framework.Bundle;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.ui.launch.ExitWithRunningSessions;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.RunningSessions;
import org.stagecraft.tools.ui.launch.SessionParts;
import org.stagecraft.tools.ui.prefs.ToolPreferences;

/**
 * When the IDE exits, its sessions stop while the plug-ins they need are still there: stopping the
 * tools.ui plug-in (what OSGi does at exit, before it stops the plug-ins tools.ui requires) stops
 * every running session before it returns, so the JVM shutdown hook finds nothing left to do.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SessionShutdownTest {
    private static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";
    private ILaunch launch;
    private Path tmp;
    private IProject project;

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-shutdown");
        project = Fixtures.projectWithWorlds("shutdown-" + System.nanoTime());
        ToolPreferences.setTools(List.of());
    }

    @AfterEach
    void tearDown() throws Exception {
        Bundle ui = Platform.getBundle("org.stagecraft.tools.ui");
        if (ui.getState() != Bundle.ACTIVE && ui.getState() != Bundle.STARTING) {
            ui.start(Bundle.START_TRANSIENT | Bundle.START_ACTIVATION_POLICY);
        }
        if (launch != null && !launch.isTerminated()) {
            launch.terminate();
        }
        project.delete(true, true, new NullProgressMonitor());
    }

    /** A session with the stand-in Player, logging into {@code logFolder} ("" for none). */
    private SessionParts launch(String logFolder) throws Exception {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("shutdown"));
        wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/pioneer-laser-sonar.cfg").getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, Fixtures.standIn(tmp).toString());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_TRACE", Fixtures.traces().resolve(TRACE).toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, Ports.free("127.0.0.1", 1).get(0));
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, logFolder);
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        launch = wc.launch(ILaunchManager.RUN_MODE, new NullProgressMonitor());
        return RobotSessionLaunchDelegate.partsOf(launch);
    }

    /**
     * Issue 24, item 2: exiting with a session running asks first; "Cancel" keeps the IDE and the
     * session; "Stop and Exit" stops the session before the workbench goes: its launch has ended, the
     * new spy log is in the project, and nothing reached the Error Log.
     */
    @Test
    void exitingWithASessionRunningAsksAndStopsItWhileTheWorkbenchIsWhole() throws Exception {
        SessionParts parts = launch("spy-logs");
        assertNotNull(parts, "the session runs");
        ProcessHandle player = parts.session().player().process();
        List<List<String>> asked = new ArrayList<>();
        ExitWithRunningSessions cancel = new ExitWithRunningSessions(names -> {
            asked.add(names);
            return false; // the user chose Cancel
        });
        assertFalse(Await.ui(() -> cancel.preShutdown(PlatformUI.getWorkbench(), false)), "Cancel: the IDE stays");
        assertEquals(List.of(List.of(parts.sessionName())), asked, "the user was asked, naming the session");
        assertFalse(launch.isTerminated(), "Cancel: the session goes on");
        assertTrue(player.isAlive());

        List<IStatus> logged = new ArrayList<>();
        ILogListener errors = (status, plugin) -> {
            if (status.matches(IStatus.ERROR)) {
                logged.add(status);
            }
        };
        Platform.addLogListener(errors);
        try {
            ExitWithRunningSessions stop = new ExitWithRunningSessions(names -> true);
            assertTrue(Await.ui(() -> stop.preShutdown(PlatformUI.getWorkbench(), false)), "Stop and Exit");
            // all of it done when preShutdown returns, while the workbench is whole
            assertTrue(launch.isTerminated(), "the session's launch has ended");
            assertFalse(player.isAlive(), "Player is gone");
            assertTrue(RunningSessions.running().isEmpty(), RunningSessions.running().toString());
            IFolder logs = project.getFolder("spy-logs");
            assertTrue(logs.exists() && logs.members().length == 1, "the new spy log is shown in the project");
        } finally {
            Platform.removeLogListener(errors);
        }
        assertEquals(List.of(), logged, "nothing in the Error Log");
    }

    @Test
    void exitingWithoutASessionAsksNothing() {
        ExitWithRunningSessions never = new ExitWithRunningSessions(names -> {
            throw new AssertionError("asked with no session running: " + names);
        });
        assertTrue(RunningSessions.running().isEmpty());
        assertTrue(Await.ui(() -> never.preShutdown(PlatformUI.getWorkbench(), false)));
    }

    @Test
    void stoppingThePluginStopsItsRunningSessionsBeforeItReturns() throws Exception {
        SessionParts parts = launch("");
        assertNotNull(parts, "the session runs");
        RobotSession session = parts.session();
        ProcessHandle player = session.player().process();
        assertNotNull(player, "Player runs");
        assertTrue(RunningSessions.running().contains(parts), "the running session is known");

        Bundle ui = Platform.getBundle("org.stagecraft.tools.ui");
        assertEquals(Bundle.ACTIVE, ui.getState(), "a session ran, so the plug-in is active");
        ui.stop(Bundle.STOP_TRANSIENT);

        // no waiting: the stop is synchronous
        assertTrue(session.isClosed(), "the session is closed when the plug-in's stop returns");
        assertFalse(player.isAlive(), "Player (pid " + player.pid() + ") is gone when the plug-in's stop returns");
        assertTrue(RunningSessions.running().isEmpty(), "nothing is left for the shutdown hook: " + RunningSessions.running());
    }
}
