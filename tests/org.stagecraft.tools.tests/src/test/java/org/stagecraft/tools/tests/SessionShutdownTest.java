package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.osgi.framework.Bundle;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.session.RobotSession;
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

    @Test
    void stoppingThePluginStopsItsRunningSessionsBeforeItReturns() throws Exception {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("shutdown"));
        wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/pioneer-laser-sonar.cfg").getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, Fixtures.standIn(tmp).toString());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_TRACE", Fixtures.traces().resolve(TRACE).toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, Ports.free("127.0.0.1", 1).get(0));
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        launch = wc.launch(ILaunchManager.RUN_MODE, new NullProgressMonitor());
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
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
