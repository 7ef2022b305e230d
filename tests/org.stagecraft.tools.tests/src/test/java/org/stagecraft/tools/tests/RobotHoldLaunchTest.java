package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.core.commands.Command;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.core.model.IThread;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.handlers.IHandlerService;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.ui.launch.EmergencyStop;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionHolds;
import org.stagecraft.tools.ui.launch.SessionParts;
import org.stagecraft.tools.ui.prefs.ToolPreferences;
import org.stagecraft.tools.ui.view.EmergencyStopHandler;
import org.stagecraft.tools.ui.view.ShowStageWindowHandler;
import org.stagecraft.tools.ui.view.ToolsModel;

/**
 * Robot holds wired into the IDE: a Robot Session (stand-in Player) whose linked launch is a debug model
 * of our own firing the platform's debug events, as PyDev's would; the emergency stop; the Tools view's
 * session row. The spy's {@link RobotHold} is what is asserted on.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotHoldLaunchTest {
    private static final Duration WAIT = Duration.ofSeconds(40);
    private static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";

    private final List<ILaunch> launches = new ArrayList<>();
    private Path tmp;
    private IProject project;
    private Path standIn;

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-hold-test");
        standIn = Fixtures.standIn(tmp);
        project = Fixtures.projectWithWorlds("hold-" + System.nanoTime());
        ToolPreferences.setTools(List.of());
        EmergencyStop.get().release();
    }

    @AfterEach
    void tearDown() throws Exception {
        EmergencyStop.get().release();
        Fixtures.terminateAll(launches, WAIT);
        project.delete(true, true, new NullProgressMonitor());
    }

    private ILaunchConfigurationWorkingCopy config() throws Exception {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("held"));
        wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/pioneer-laser-sonar.cfg").getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, standIn.toString());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_TRACE", Fixtures.traces().resolve(TRACE).toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, Ports.free("127.0.0.1", 1).get(0));
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        return wc;
    }

    private SessionParts launch(ILaunchConfigurationWorkingCopy wc) throws CoreException {
        ILaunch l = wc.launch(ILaunchManager.DEBUG_MODE, new NullProgressMonitor());
        launches.add(l);
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(l);
        assertNotNull(parts, "the session runs when launch returns");
        return parts;
    }

    private static String sessionRow(SessionParts parts) {
        ToolsModel.Row row = ToolsModel.get().find(parts.sessionName(), SessionParts.SESSION_PART);
        return row == null ? null : row.state() + " " + row.detail();
    }

    @Test
    void aSuspendedThreadOfALinkedLaunchHoldsTheRobotsUntilEveryThreadRunsAgain() throws Exception {
        SessionParts parts = launch(config()); // hold while suspended: on by default
        RobotSession session = parts.session();
        RobotHold hold = session.holds();
        assertTrue(session.config().spy().holdWhenSuspended(), "the option is on by default");
        assertTrue(hold.isEnabled(), "holds were enabled before the spy accepted anyone");
        assertEquals(Duration.ofSeconds(5), session.spy().upstreamGrace());
        FakeDebug program = new FakeDebug(2);
        IThread a = program.threads.get(0), b = program.threads.get(1);

        // not linked yet: the program's events are someone else's
        FakeDebug.fire(FakeDebug.event(a, DebugEvent.SUSPEND, DebugEvent.BREAKPOINT));
        assertFalse(hold.isHeld(), "a launch that is not the session's holds nothing");
        FakeDebug.fire(FakeDebug.event(a, DebugEvent.RESUME, DebugEvent.CLIENT_REQUEST));

        parts.link(program.launch);
        SessionHolds holds = SessionHolds.of(program.launch);
        assertNotNull(holds, "the session's holds are found from the linked launch");
        assertSame(hold, holds.hold());
        assertSame(holds, SessionHolds.of(parts.launches().get(0)), "... and from the session's own launch");

        FakeDebug.fire(FakeDebug.event(a, DebugEvent.SUSPEND, DebugEvent.BREAKPOINT));
        assertTrue(hold.isHeld(), "a breakpoint holds");
        assertEquals(Map.of(HoldReason.SUSPENDED, 1), hold.reasons());
        String row = sessionRow(parts);
        assertTrue(row.startsWith("READY held") && row.contains("suspended in the debugger"), row);

        FakeDebug.fire(FakeDebug.event(b, DebugEvent.SUSPEND, DebugEvent.CLIENT_REQUEST));
        assertEquals(Map.of(HoldReason.SUSPENDED, 1), hold.reasons(), "one hold for the session, however many threads");
        FakeDebug.fire(FakeDebug.event(a, DebugEvent.RESUME, DebugEvent.CLIENT_REQUEST));
        assertTrue(hold.isHeld(), "thread b is still suspended");
        // a hover evaluation runs code in b for a moment: the robot must not twitch
        FakeDebug.fire(FakeDebug.event(b, DebugEvent.RESUME, DebugEvent.EVALUATION_IMPLICIT),
                FakeDebug.event(b, DebugEvent.SUSPEND, DebugEvent.EVALUATION_IMPLICIT));
        assertTrue(hold.isHeld(), "an implicit evaluation does not release");
        FakeDebug.fire(FakeDebug.event(b, DebugEvent.RESUME, DebugEvent.STEP_OVER));
        assertFalse(hold.isHeld(), "every thread runs: released");
        assertEquals(Map.of(), hold.reasons());
        assertTrue(sessionRow(parts).startsWith("READY running"), sessionRow(parts));

        // a step ends suspended again; the target ending releases everything it had suspended
        FakeDebug.fire(FakeDebug.event(a, DebugEvent.SUSPEND, DebugEvent.STEP_END));
        assertTrue(hold.isHeld());
        FakeDebug.fire(FakeDebug.event(program.target, DebugEvent.TERMINATE, DebugEvent.UNSPECIFIED));
        assertFalse(hold.isHeld(), "the program's end releases");

        // a target that suspends as a whole (no thread events) holds too, and its resume releases
        FakeDebug.fire(FakeDebug.event(program.target, DebugEvent.SUSPEND, DebugEvent.CLIENT_REQUEST));
        assertTrue(hold.isHeld());
        FakeDebug.fire(FakeDebug.event(program.target, DebugEvent.RESUME, DebugEvent.CLIENT_REQUEST));
        assertFalse(hold.isHeld());
    }

    @Test
    void aLaunchLinkedWhileItsProgramIsSuspendedHoldsAtOnceAndTheSessionsEndReleases() throws Exception {
        SessionParts parts = launch(config());
        RobotHold hold = parts.session().holds();
        FakeDebug program = new FakeDebug(1);
        program.suspendedNow.add(program.threads.get(0)); // "stop at first line" before the link existed
        parts.link(program.launch);
        assertTrue(hold.isHeld(), "the link found the suspended thread");

        ILaunch launch = parts.launches().get(0);
        launch.terminate();
        Await.until("the launch is terminated", WAIT, launch::isTerminated);
        assertFalse(hold.isHeld(), "the ended session took its hold back");
        assertNull(SessionHolds.of(program.launch), "an ended session is not found any more");
        FakeDebug.fire(FakeDebug.event(program.threads.get(0), DebugEvent.SUSPEND, DebugEvent.BREAKPOINT));
        assertFalse(hold.isHeld(), "and no longer listens");
    }

    @Test
    void withTheOptionOffTheDebuggerHoldsNothingAndTheSpyStaysAPlainCopy() throws Exception {
        ILaunchConfigurationWorkingCopy wc = config();
        wc.setAttribute(LaunchAttributes.HOLD_WHEN_SUSPENDED, false);
        wc.setAttribute(LaunchAttributes.UPSTREAM_GRACE_SECONDS, 2);
        SessionParts parts = launch(wc);
        RobotHold hold = parts.session().holds();
        assertFalse(hold.isEnabled());
        assertEquals(Duration.ofSeconds(2), parts.session().spy().upstreamGrace());
        assertNull(parts.holds().suspendHold());
        FakeDebug program = new FakeDebug(1);
        parts.link(program.launch);
        FakeDebug.fire(FakeDebug.event(program.threads.get(0), DebugEvent.SUSPEND, DebugEvent.BREAKPOINT));
        assertEquals(Map.of(), hold.reasons(), "no hold was asked for");
        assertEquals(1, EmergencyStop.get().unholdable(), "the emergency stop knows it cannot stop this session");
        assertTrue(EmergencyStop.get().tooltip().contains("1 running session has holds off"), EmergencyStop.get().tooltip());
    }

    @Test
    void theWatchdogAloneEnablesHoldsSoTheEmergencyStopWorks() throws Exception {
        ILaunchConfigurationWorkingCopy wc = config();
        wc.setAttribute(LaunchAttributes.HOLD_WHEN_SUSPENDED, false);
        wc.setAttribute(LaunchAttributes.WATCHDOG, true);
        wc.setAttribute(LaunchAttributes.WATCHDOG_MILLIS, 1500);
        SessionParts parts = launch(wc);
        RobotHold hold = parts.session().holds();
        assertTrue(hold.isEnabled());
        assertEquals(Duration.ofMillis(1500), hold.watchdog());
        EmergencyStop.get().engage();
        assertEquals(Map.of(HoldReason.EMERGENCY_STOP, 1), hold.reasons());
    }

    /**
     * Issue 24, item 6: Show Stage's Window is a command of the workbench; a session that cannot raise a Stage
     * window (here its Player is a stand-in, with no Stage world) says why instead of doing nothing. The raise
     * itself is tested against real Stage (RealWorldFreezeTest).
     */
    @Test
    void showStagesWindowSaysWhyASessionHasNoWindowToRaise() throws Exception {
        SessionParts parts = launch(config());
        AtomicReference<Boolean> handled = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            Command c = PlatformUI.getWorkbench().getService(ICommandService.class).getCommand(ShowStageWindowHandler.COMMAND);
            handled.set(c.isDefined() && c.isHandled());
        });
        assertTrue(handled.get(), "the command is contributed and handled");
        List<String> said = ShowStageWindowHandler.raiseAll();
        assertTrue(said.stream().anyMatch(t -> t.startsWith(parts.sessionName() + ": no world driver in this session")
                && t.contains(parts.session().worldProblem())), said.toString());
    }

    @Test
    void theEmergencyStopButtonHoldsEveryRunningSessionAndNewOnesUntilPressedAgain() throws Exception {
        SessionParts first = launch(config());
        RobotHold one = first.session().holds();

        AtomicReference<Boolean> checked = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand(EmergencyStopHandler.COMMAND, null);
                Command c = PlatformUI.getWorkbench().getService(ICommandService.class).getCommand(EmergencyStopHandler.COMMAND);
                checked.set(c.isDefined() && c.isHandled());
            } catch (Exception e) {
                throw new RuntimeException(e);
            }
        });
        assertTrue(checked.get(), "the command is contributed and handled");
        assertTrue(EmergencyStop.get().isEngaged(), "the button engaged the stop");
        assertTrue(one.isHeld());
        assertEquals(Map.of(HoldReason.EMERGENCY_STOP, 1), one.reasons());
        String row = sessionRow(first);
        assertTrue(row.startsWith("READY held") && row.contains("emergency stop"), row);

        SessionParts second = launch(config());
        RobotHold two = second.session().holds();
        assertTrue(two.isHeld(), "a session started during the stop is held from its start");
        assertEquals(2, EmergencyStop.get().sessions());

        // a suspend during the stop, then the release: the debugger's hold stays
        FakeDebug program = new FakeDebug(1);
        first.link(program.launch);
        FakeDebug.fire(FakeDebug.event(program.threads.get(0), DebugEvent.SUSPEND, DebugEvent.BREAKPOINT));
        Display.getDefault().syncExec(() -> {
            try {
                PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand(EmergencyStopHandler.COMMAND, null);
            } catch (Exception e) {
                throw new RuntimeException(e);
            }
        });
        assertFalse(EmergencyStop.get().isEngaged());
        assertFalse(two.isHeld(), "released");
        assertEquals(Map.of(HoldReason.SUSPENDED, 1), one.reasons(), "the suspended program keeps its robots held");
        assertEquals(ToolState.READY, ToolsModel.get().find(first.sessionName(), SessionParts.SESSION_PART).state());
    }
}
