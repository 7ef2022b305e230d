package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.spy.breakpoint.BreakpointHit;
import org.stagecraft.spy.breakpoint.DataBreakpoints;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.ui.breakpoints.RobotDataBreakpoint;
import org.stagecraft.tools.ui.breakpoints.RobotDataBreakpointPresentation;
import org.stagecraft.tools.ui.breakpoints.RobotDataBreakpoints;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionParts;
import org.stagecraft.tools.ui.prefs.ToolPreferences;

/**
 * Robot data breakpoints in the workbench: the platform breakpoint (persisted marker, condition refused with
 * where and why, hit count, label), and a Robot Session (stand-in Player serving recorded traffic) whose
 * spy holds at the first laser scan nearer than 1 m, asks the program's debug target to suspend, lets the
 * message go on only once the target reports SUSPEND, and ends the hit on the user's Resume, not on a step.
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class RobotDataBreakpointLaunchTest {
    private static final Duration WAIT = Duration.ofSeconds(40);
    private static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";

    private final List<ILaunch> launches = new ArrayList<>();
    private Path tmp;
    private IProject project;

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-data-breakpoint-test");
        project = Fixtures.projectWithWorlds("data-break-" + System.nanoTime());
        ToolPreferences.setTools(List.of());
        removeAll();
    }

    @AfterEach
    void tearDown() throws Exception {
        removeAll();
        Fixtures.terminateAll(launches, WAIT);
        project.delete(true, true, new NullProgressMonitor());
    }

    private static void removeAll() throws CoreException {
        for (RobotDataBreakpoint b : RobotDataBreakpoints.all()) {
            DebugPlugin.getDefault().getBreakpointManager().removeBreakpoint(b, true);
        }
    }

    @Test
    void aRobotDataBreakpointIsAPlatformBreakpointWithItsConditionAndHitCount() throws Exception {
        RobotDataBreakpoint b = RobotDataBreakpoint.create("  laser:0 min(ranges) < 30 cm ", 0);
        assertTrue(List.of(DebugPlugin.getDefault().getBreakpointManager().getBreakpoints(RobotDataBreakpoint.MODEL)).contains(b));
        IMarker m = b.getMarker();
        assertEquals(RobotDataBreakpoint.MARKER, m.getType());
        assertTrue(m.getAttribute(org.eclipse.debug.core.model.IBreakpoint.PERSISTED, false), "kept with the workspace");
        assertEquals("laser:0 min(ranges) < 30 cm", b.condition());
        assertTrue(b.isEnabled());
        assertEquals("Robot data: laser:0 min(ranges) < 30 cm", RobotDataBreakpointPresentation.label(b));
        String[] shown = new String[2];
        org.eclipse.swt.widgets.Display.getDefault().syncExec(() -> {
            org.eclipse.debug.ui.IDebugModelPresentation p = org.eclipse.debug.ui.DebugUITools.newDebugModelPresentation();
            shown[0] = p.getText(b);
            shown[1] = p.getImage(b) == null ? "no image" : "an image";
            p.dispose();
        });
        assertEquals("Robot data: laser:0 min(ranges) < 30 cm", shown[0], "what the Breakpoints view shows");
        assertEquals("an image", shown[1]);

        b.setHitCount(3);
        assertEquals(3, b.hitCount());
        assertEquals("Robot data: laser:0 min(ranges) < 30 cm [hit count: 3]", RobotDataBreakpointPresentation.label(b));

        CoreException bad = assertThrows(CoreException.class, () -> b.setCondition("laser:0 min(ranges) < 30 deg"));
        assertTrue(bad.getMessage().contains("at character 23: '30 deg' is an angle"), bad.getMessage());
        assertEquals("laser:0 min(ranges) < 30 cm", b.condition(), "a refused condition changes nothing");
        assertEquals("at character 1: no Player interface is called 'lidar' (e.g. position2d, laser, ranger)",
                RobotDataBreakpoint.problem("lidar min(ranges) < 1"));
        assertThrows(CoreException.class, () -> RobotDataBreakpoint.create("laser:0", 0));
    }

    private SessionParts launch() throws Exception {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("data-break"));
        wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/pioneer-laser-sonar.cfg").getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, Fixtures.standIn(tmp).toString());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_TRACE", Fixtures.traces().resolve(TRACE).toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, Ports.free("127.0.0.1", 1).get(0));
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        ILaunch l = wc.launch(ILaunchManager.DEBUG_MODE, new NullProgressMonitor());
        launches.add(l);
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(l);
        assertNotNull(parts, "the session runs when launch returns");
        return parts;
    }

    @Test
    void aHitSuspendsTheProgramPassesTheMessageOnWhenSuspendedAndEndsOnResume() throws Exception {
        RobotDataBreakpoint b = RobotDataBreakpoint.create("laser:0 min(ranges) < 1.0", 0);
        SessionParts parts = launch();
        RobotHold hold = parts.session().holds();
        assertNotNull(parts.holds().dataBreakpoints(), "holds are on: so are robot data breakpoints");
        DataBreakpoints spy = parts.holds().dataBreakpoints().spy();
        Await.until("the session's spy has the workbench's breakpoint", WAIT, () -> spy.breakpoints().size() == 1);
        spy.passOnBound(Duration.ofSeconds(60)); // here only the debugger's SUSPEND may pass the message on
        parts.holds().dataBreakpoints().suspendSettle(Duration.ofSeconds(60));
        FakeDebug program = new FakeDebug(1);
        parts.link(program.launch);

        RecordedConnection recorded = RecordedConnection.read(Fixtures.traces().resolve(TRACE)).get(0);
        int port = parts.session().portMap().keySet().iterator().next();
        CompletableFuture<ReplayPeer.Result> client = CompletableFuture.supplyAsync(() -> {
            try {
                return ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), recorded);
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        Await.until("the breakpoint held on the recording's near scans", WAIT, () -> spy.current() != null);
        BreakpointHit hit = spy.current();
        assertTrue(hit.why().startsWith("laser:0 min(ranges) = "), hit.why());
        Await.until("the program's debug target was asked to suspend", WAIT, () -> program.suspendRequests.get() == 1);
        assertTrue(hold.reasons().containsKey(HoldReason.DATA_BREAKPOINT), hold.reasons().toString());
        // the Debug view says why: the session's Network Spy line carries the breakpoint and its values
        String spyLine = parts.part(SessionParts.SPY_PART).getLabel();
        assertEquals("Network Spy — stopped: " + hit.why(), spyLine);
        assertFalse(hit.passedOn(), "the message waits for the program to be suspended");
        assertFalse(client.isDone());

        FakeDebug.fire(FakeDebug.event(program.threads.get(0), DebugEvent.SUSPEND, DebugEvent.CLIENT_REQUEST));
        Await.until("the message to go on once the program is suspended", WAIT, hit::passedOn);
        assertEquals("the program was suspended in the debugger", hit.passedOnWhy());
        assertTrue(client.get(60, TimeUnit.SECONDS).matches(), "every byte reached the program, in order");
        Await.until("the breakpoint to show its last hit", WAIT, () -> b.lastHit().equals(hit.why()), b::lastHit);

        FakeDebug.fire(FakeDebug.event(program.threads.get(0), DebugEvent.RESUME, DebugEvent.STEP_OVER));
        assertEquals(hit, spy.current(), "a step does not end the hit: the robots stay held while stepping");
        assertTrue(hold.reasons().containsKey(HoldReason.DATA_BREAKPOINT));
        FakeDebug.fire(FakeDebug.event(program.threads.get(0), DebugEvent.SUSPEND, DebugEvent.STEP_END),
                FakeDebug.event(program.threads.get(0), DebugEvent.RESUME, DebugEvent.CLIENT_REQUEST));
        assertNull(spy.current(), "Resume ends the hit");
        assertFalse(hold.reasons().containsKey(HoldReason.DATA_BREAKPOINT), hold.reasons().toString());
        Await.until("the spy's line to lose the reason once the hit ends", WAIT,
                () -> parts.part(SessionParts.SPY_PART).getLabel().equals(SessionParts.SPY_PART), () -> parts.part(SessionParts.SPY_PART).getLabel());

        // a program that only stops once its read returns: the message goes on a settle time after the request
        parts.holds().dataBreakpoints().suspendSettle(Duration.ofMillis(100));
        spy.add(new org.stagecraft.spy.breakpoint.DataBreakpoint("again", spy.breakpoints().get(0).condition()));
        CompletableFuture<ReplayPeer.Result> second = CompletableFuture.supplyAsync(() -> {
            try {
                return ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), recorded);
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        Await.until("held, then passed on after the settle time", WAIT, () -> spy.current() != null && spy.current().passedOn());
        assertTrue(spy.current().passedOnWhy().startsWith("the program was asked to suspend"), spy.current().passedOnWhy());
        assertEquals(2, program.suspendRequests.get());
        assertTrue(second.get(60, TimeUnit.SECONDS).matches());
        FakeDebug.fire(FakeDebug.event(program.threads.get(0), DebugEvent.RESUME, DebugEvent.CLIENT_REQUEST));
        assertNull(spy.current());
        spy.remove("again");

        // disabling it in the Breakpoints view reaches the spy
        b.setEnabled(false);
        Await.until("disabling it to reach the spy", WAIT, () -> !spy.breakpoints().get(0).enabled());
        DebugPlugin.getDefault().getBreakpointManager().removeBreakpoint(b, true);
        Await.until("removing it to reach the spy", WAIT, () -> spy.breakpoints().isEmpty());
    }
}
