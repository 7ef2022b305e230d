package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.ILogListener;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.core.model.IProcess;
import org.eclipse.debug.ui.DebugUITools;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.console.IConsole;
import org.eclipse.ui.console.TextConsole;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.types.ToolDefinition;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.PythonClientPath;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionParts;
import org.stagecraft.tools.ui.prefs.ToolPreferences;
import org.stagecraft.tools.ui.view.ToolsModel;
import org.stagecraft.tools.ui.view.ToolsView;

/**
 * Robot Sessions launched for real in the workbench, with a stand-in for Player (a Python script
 * that is run like Player, reads the rewritten cfg with a parser of its own, listens where it says
 * and serves a recorded Player conversation).
 */
@Timeout(value = 180, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
@LogsErrors({ "flaky failed: exited with exit code 3", "bad Player configuration: .*bad\\.cfg:4", "cannot run '/nonexistent/stagecraft/player'" })
class RobotSessionLaunchTest {
    private static final Duration WAIT = Duration.ofSeconds(40);
    private static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";

    private final List<IStatus> errorLog = new CopyOnWriteArrayList<>();
    private final ILogListener logListener = (status, plugin) -> errorLog.add(status);
    private final List<ILaunch> launches = new ArrayList<>();
    /** Peers block in socket reads: each on a virtual thread, never the (tiny) common pool. */
    private final ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor();
    private Path tmp;
    private IProject project;
    private Path standIn;

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-tools-test");
        standIn = Fixtures.standIn(tmp);
        project = Fixtures.projectWithWorlds("robot-" + System.nanoTime());
        ILog.of(Platform.getBundle("org.stagecraft.tools.ui")).addLogListener(logListener);
        ToolPreferences.setTools(List.of());
    }

    @AfterEach
    void tearDown() throws Exception {
        Fixtures.terminateAll(launches, WAIT);
        ILog.of(Platform.getBundle("org.stagecraft.tools.ui")).removeLogListener(logListener);
        ToolPreferences.setTools(List.of());
        peers.shutdownNow();
        project.delete(true, true, new NullProgressMonitor());
    }

    private ILaunchConfigurationWorkingCopy config(IFile cfg, int port) throws CoreException {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("session"));
        wc.setAttribute(LaunchAttributes.CFG, cfg.getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, standIn.toString());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_TRACE", Fixtures.traces().resolve(TRACE).toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, port);
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "spy-logs");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        return wc;
    }

    private ILaunch launch(ILaunchConfigurationWorkingCopy wc) throws CoreException {
        ILaunch l = wc.launch(ILaunchManager.RUN_MODE, new NullProgressMonitor());
        launches.add(l);
        return l;
    }

    private static IProcess process(ILaunch launch, String label) {
        return Arrays.stream(launch.getProcesses()).filter(p -> p.getLabel().equals(label)).findFirst()
                .orElseThrow(() -> new AssertionError("no process '" + label + "' in " + Arrays.stream(launch.getProcesses())
                        .map(IProcess::getLabel).toList()));
    }

    /** The text of the process's console, once the debug UI has made one. */
    private static String consoleText(IProcess p) {
        AtomicReference<String> text = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            IConsole c = DebugUITools.getConsole(p);
            text.set(c instanceof TextConsole t ? t.getDocument().get() : null);
        });
        return text.get();
    }

    private static void awaitConsole(IProcess p, String contains) {
        Await.until("the console of " + p.getLabel() + " shows '" + contains + "'", WAIT,
                () -> consoleText(p) != null && consoleText(p).contains(contains), () -> "; it shows: " + consoleText(p));
    }

    @Test
    void aSessionRelaysPlayerByteExactLogsItShowsEveryPartAndStopsCleanly() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        IFile cfg = project.getFile("worlds/pioneer-laser-sonar.cfg");
        IFile robot = Fixtures.write(project, "robot.py", """
                import os, socket
                s = socket.create_connection(("127.0.0.1", int(os.environ["ROBOT_PORT"])))
                banner = b""
                while len(banner) < 32:
                    chunk = s.recv(32 - len(banner))
                    if not chunk:
                        break
                    banner += chunk
                print("banner " + banner.rstrip(b"\\0").decode())
                s.close()
                """);
        ILaunchConfigurationWorkingCopy wc = config(cfg, port);
        wc.setAttribute(LaunchAttributes.PROGRAM, robot.getFullPath().toString());
        wc.setAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, Map.of("ROBOT_PORT", String.valueOf(port)));
        RecordedConnection recorded = RecordedConnection.read(Fixtures.traces().resolve(TRACE)).get(0);

        // the views listen on the workbench bus: the session's messages must reach it
        CountDownLatch poseOnWorkbenchBus = new CountDownLatch(1);
        Subscription workbench = WorkbenchBus.get().subscribe(StreamPattern.parse("src=*:" + port + " type=1 dev=4 subtype=1"),
                DeliveryPolicy.latestValue(), m -> poseOnWorkbenchBus.countDown());

        ILaunch launch = launch(wc);
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
        assertNotNull(parts, "the session runs when launch returns");
        RobotSession session = parts.session();

        // Player on a moved port, from the rewritten copy; the spy on the original one
        assertEquals(List.of(port), List.copyOf(session.portMap().keySet()));
        int moved = session.portMap().get(port);
        assertNotEquals(port, moved);
        Path copy = session.rewritten().main();
        assertTrue(copy.startsWith(session.scratchDirectory()));
        assertTrue(Files.readString(copy).contains("worldfile \"" + cfg.getLocation().toPath().getParent()
                .resolve("pioneer-laser-sonar.world") + "\""), "the world file still resolves from the copy");
        assertEquals(ToolState.READY, session.player().state(), "readiness: Player's ports were open before the spy started");
        ProcessHandle player = session.player().process();
        assertTrue(player.isAlive());
        assertFalse(Ports.isFree("127.0.0.1", port), "the spy listens on the original port");

        // one launch with every part, each with its own console
        IProcess playerPart = process(launch, RobotSession.PLAYER_TOOL_NAME);
        IProcess spyPart = process(launch, SessionParts.SPY_PART);
        IProcess program = process(launch, "robot.py (python3)");
        awaitConsole(playerPart, "standin: listening on " + moved);
        awaitConsole(playerPart, "paths=ok");
        awaitConsole(spyPart, "robot programs connect to 127.0.0.1:" + port + "  ->  Player on 127.0.0.1:" + moved);
        // the robot program ran unchanged against the original port, through the spy
        Await.until("the robot program ended", WAIT, program::isTerminated);
        assertEquals(0, program.getExitValue());
        awaitConsole(program, "banner Player v.3.1.1");

        // a client peer replays the recorded client side through the spy: byte-exact both ways
        CompletableFuture<ReplayPeer.Result> client = CompletableFuture.supplyAsync(() -> {
            try {
                return ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), recorded);
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        }, peers);
        ReplayPeer.Result r = client.get(60, TimeUnit.SECONDS);
        assertTrue(r.matches(), "the client got Player's recorded bytes; first difference at " + r.firstDifference());
        awaitConsole(playerPart, "served port=" + moved + " bytes_in=" + recorded.clientBytes().length + " match=true");
        assertTrue(poseOnWorkbenchBus.await(30, TimeUnit.SECONDS), "position2d data of the session on the workbench bus");
        workbench.close();

        // the Tools view shows the parts and their states; the program's row follows its process's end,
        // which the debug platform announces on a thread of its own
        Await.until("the program's row says it exited", WAIT, () -> {
            ToolsModel.Row row = ToolsModel.get().find(launch.getLaunchConfiguration().getName(), "robot.py");
            return row != null && row.state() == ToolState.EXITED;
        });
        AtomicReference<List<String>> shown = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                ToolsView view = (ToolsView) PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage()
                        .showView(ToolsView.ID);
                List<String> rows = new ArrayList<>();
                for (int i = 0; i < view.rowCount(); i++) {
                    rows.add(view.cell(i, 0) + "|" + view.cell(i, 1) + "|" + view.cell(i, 2));
                }
                shown.set(rows);
            } catch (Exception e) {
                throw new RuntimeException(e);
            }
        });
        String name = launch.getLaunchConfiguration().getName();
        assertTrue(shown.get().contains(name + "|Player|ready"), shown.get().toString());
        assertTrue(shown.get().contains(name + "|Network Spy|ready"), shown.get().toString());
        // the robot program is a part too (issue 24, item 9): it ran and ended by itself
        assertTrue(shown.get().contains(name + "|robot.py|exited"), shown.get().toString());
        assertEquals(0, ToolsModel.get().find(name, "robot.py").lastExit());
        // the spy's PID is the workbench's own: the row says why
        assertTrue(ToolsModel.get().find(name, SessionParts.SPY_PART).detail().endsWith(SessionParts.INSIDE_THE_WORKBENCH),
                ToolsModel.get().find(name, SessionParts.SPY_PART).detail());
        assertEquals(ProcessHandle.current().pid(), ToolsModel.get().find(name, SessionParts.SPY_PART).pid());

        // terminating the launch stops everything
        Path scratch = session.scratchDirectory();
        launch.terminate();
        Await.until("the launch is terminated", WAIT, launch::isTerminated);
        assertTrue(session.isClosed());
        assertFalse(player.isAlive(), "Player's process is gone");
        assertEquals(List.of(), player.descendants().toList());
        assertTrue(Ports.isFree("127.0.0.1", port), "the original port is free");
        assertTrue(Ports.isFree("127.0.0.1", moved), "Player's port is free");
        assertFalse(Files.exists(scratch), "the rewritten cfg was removed");
        for (IProcess p : launch.getProcesses()) {
            assertTrue(p.isTerminated(), p.getLabel());
        }
        assertEquals(ToolState.STOPPED, ToolsModel.get().find(name, "Player").state());
        // the program and the replayed client: two connections, said as such (and one as one)
        assertEquals("2 connections relayed", ToolsModel.get().find(name, SessionParts.SPY_PART).detail());
        assertEquals("1 connection relayed", SessionParts.relayed(1));

        // the spy log is in the project and holds the traffic
        Await.until("the spy log appears in the project", WAIT, () -> {
            try {
                return project.getFolder("spy-logs").exists() && project.getFolder("spy-logs").members().length == 1;
            } catch (CoreException e) {
                return false;
            }
        });
        IFile log = (IFile) project.getFolder("spy-logs").members()[0];
        assertTrue(log.getName().startsWith("pioneer-laser-sonar-") && log.getName().endsWith(".mcap"), log.getName());
        try (SpyLogReader reader = SpyLogReader.open(log.getLocation().toPath())) {
            assertFalse(reader.recovered(), "the log was closed properly");
            List<LogConnection> conns = reader.connections();
            assertEquals(2, conns.size(), "the robot program's and the replayed client's connections: " + conns);
            LogConnection replayed = null;
            for (LogConnection c : conns) {
                assertEquals(port, c.port());
                if (Arrays.equals(recorded.clientBytes(), reader.streamBytes(c.conn(), Direction.CLIENT_TO_SERVER))) {
                    replayed = c;
                }
            }
            assertNotNull(replayed, "the replayed client's bytes are in the log");
            assertArrayEquals(recorded.serverBytes(), reader.streamBytes(replayed.conn(), Direction.SERVER_TO_CLIENT));
        }
    }

    @Test
    void theRobotProgramFindsStagecraftsPythonClientAfterItsOwnPythonPath() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        IFile robot = Fixtures.write(project, "robot.py", """
                import importlib.util, os
                spec = importlib.util.find_spec("stagecraft_player")
                print("client " + (spec.origin if spec else "missing"))
                print("pythonpath " + os.environ.get("PYTHONPATH", ""))
                """);
        Path userLibs = Files.createDirectories(tmp.resolve("user-libs"));
        ILaunchConfigurationWorkingCopy wc = config(project.getFile("worlds/pioneer-laser-sonar.cfg"), port);
        wc.setAttribute(LaunchAttributes.PROGRAM, robot.getFullPath().toString());
        wc.setAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, Map.of("PYTHONPATH", userLibs.toString()));
        ILaunch launch = launch(wc);
        IProcess program = process(launch, "robot.py (python3)");
        Await.until("the robot program ended", WAIT, program::isTerminated);
        assertEquals(0, program.getExitValue());

        String folder = PythonClientPath.folder().orElseThrow();
        assertTrue(Files.isRegularFile(Path.of(folder, "stagecraft_player", "__init__.py")), folder);
        awaitConsole(program, "client " + Path.of(folder, "stagecraft_player", "__init__.py"));
        awaitConsole(program, "pythonpath " + userLibs + java.io.File.pathSeparator + folder + "\n");
        assertEquals("a:b", PythonClientPath.append("a:b", "b"), "a folder already there is not added twice");
        assertEquals("x", PythonClientPath.append("", "x"));
        launch.terminate();
        Await.until("the launch is terminated", WAIT, launch::isTerminated);
    }

    /**
     * A running session's launch removed (the Debug view's Remove, or Terminate and Remove): its console goes
     * with it, and the parts, still writing while they stop, write to no console. (Before, the PyDev tier met
     * "Error logged from Debug UI: Output Stream is closed": a part's stopping lines raced the disposal of its
     * console.) The Error Log guard checks the log; the listener added after the removal shows that the
     * stopping lines reach no one.
     */
    @Test
    void aRemovedSessionsPartsWriteToNoConsole() throws Exception {
        IFile cfg = project.getFile("worlds/pioneer-laser-sonar.cfg");
        int port = Ports.free("127.0.0.1", 1).get(0);
        ILaunch launch = launch(config(cfg, port));
        IProcess playerPart = process(launch, RobotSession.PLAYER_TOOL_NAME);
        awaitConsole(playerPart, "standin: listening on ");
        DebugPlugin.getDefault().getLaunchManager().removeLaunch(launch);
        List<String> after = new java.util.concurrent.CopyOnWriteArrayList<>();
        playerPart.getStreamsProxy().getOutputStreamMonitor().addListener((text, monitor) -> after.add(text));
        launch.terminate();
        Await.until("the launch is terminated", WAIT, launch::isTerminated);
        assertEquals(List.of(), after, "what the stopping part wrote after its launch was removed");
    }

    @Test
    void aToolCrashIsReportedAndRestartedAsItsPolicySays() throws Exception {
        ToolPreferences.setTools(List.of(new ToolDefinition("flaky", null, "sh",
                "-c 'echo ready; read line; echo crashing; exit 3'", "", Map.of(), "line:^ready$", "on-failure:1", 20, true)));
        ILaunchConfigurationWorkingCopy wc = config(project.getFile("worlds/pioneer-laser-sonar.cfg"),
                Ports.free("127.0.0.1", 1).get(0));
        wc.removeAttribute(LaunchAttributes.TOOLS); // every enabled tool
        ILaunch launch = launch(wc);
        String name = launch.getLaunchConfiguration().getName();
        IProcess flaky = process(launch, "flaky");
        assertEquals(ToolState.READY, ToolsModel.get().find(name, "flaky").state());
        long firstPid = ToolsModel.get().find(name, "flaky").pid();

        // a crash mid-session, triggered through the tool's console input
        flaky.getStreamsProxy().write("crash\n");
        Await.until("flaky is ready again after its restart", WAIT, () -> {
            ToolsModel.Row row = ToolsModel.get().find(name, "flaky");
            return row.state() == ToolState.READY && row.restarts() == 1;
        }, () -> String.valueOf(ToolsModel.get().find(name, "flaky")));
        assertNotEquals(firstPid, ToolsModel.get().find(name, "flaky").pid());
        assertEquals(3, ToolsModel.get().find(name, "flaky").lastExit());
        assertTrue(errorLog.stream().anyMatch(s -> s.getSeverity() == IStatus.WARNING
                && s.getMessage().contains("flaky exited with exit code 3; restart 1 of 1")), errorLog.toString());
        awaitConsole(flaky, "crashing");
        awaitConsole(flaky, "[stagecraft] restarting: exited with exit code 3; restart 1 of 1");
        assertFalse(flaky.isTerminated(), "the restarted tool is the same part of the session");

        // the second crash uses up the policy: reported as an error, the tool stays down, the session goes on
        flaky.getStreamsProxy().write("crash\n");
        Await.until("flaky is down for good", WAIT, flaky::isTerminated);
        assertEquals(3, flaky.getExitValue());
        assertEquals(ToolState.FAILED, ToolsModel.get().find(name, "flaky").state());
        assertTrue(errorLog.stream().anyMatch(s -> s.getSeverity() == IStatus.ERROR
                && s.getMessage().contains("flaky failed: exited with exit code 3")), errorLog.toString());
        awaitConsole(flaky, "not restarted (1 of 1 restarts used)");
        assertFalse(launch.isTerminated());
        assertEquals(ToolState.READY, RobotSessionLaunchDelegate.partsOf(launch).session().player().state());

        launch.terminate();
        Await.until("the launch is terminated", WAIT, launch::isTerminated);
    }

    @Test
    void aMissingPlayerFailsTheLaunchNamingItAndLeavesNothing() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        ToolPreferences.setTools(List.of(new ToolDefinition("helper", null, "sh", "-c 'echo helper up; exec sleep 301'", "",
                Map.of(), "line:helper up", "never", 20, true)));
        ILaunchConfigurationWorkingCopy wc = config(project.getFile("worlds/pioneer-laser-sonar.cfg"), port);
        wc.setAttribute(LaunchAttributes.PLAYER, "/nonexistent/stagecraft/player");
        wc.removeAttribute(LaunchAttributes.TOOLS);
        CoreException e = assertThrows(CoreException.class, () -> launch(wc));
        assertTrue(e.getMessage().contains("tool 'Player': cannot run '/nonexistent/stagecraft/player': no such file"),
                e.getMessage());
        String name = wc.getName();
        assertEquals(ToolState.STOPPED, ToolsModel.get().find(name, "helper").state(), "the tool started first was stopped");
        assertEquals(ToolState.FAILED, ToolsModel.get().find(name, "Player").state());
        assertTrue(errorLog.stream().anyMatch(s -> s.getSeverity() == IStatus.ERROR
                && s.getMessage().contains("/nonexistent/stagecraft/player")), errorLog.toString());
        assertTrue(Ports.isFree("127.0.0.1", port));
        try (Stream<ProcessHandle> children = ProcessHandle.current().children()) {
            assertTrue(children.noneMatch(h -> h.info().commandLine().orElse("").contains("sleep 301")),
                    "no tool process is left");
        }
    }

    @Test
    void aBadCfgFailsTheLaunchNamingFileAndLine() throws Exception {
        IFile bad = Fixtures.write(project, "worlds/bad.cfg", "driver\n(\n  name \"stage\"\n  provides [ \"position2d:zero\" ]\n)\n");
        CoreException e = assertThrows(CoreException.class, () -> launch(config(bad, Ports.free("127.0.0.1", 1).get(0))));
        assertTrue(e.getMessage().contains(bad.getLocation().toOSString() + ":4: provides: 'position2d:zero' has index 'zero'"),
                e.getMessage());
    }
}
