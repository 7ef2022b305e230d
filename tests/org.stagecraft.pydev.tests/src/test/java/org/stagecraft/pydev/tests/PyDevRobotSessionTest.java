package org.stagecraft.pydev.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.core.model.IBreakpoint;
import org.eclipse.debug.core.model.IProcess;
import org.eclipse.debug.core.model.IThread;
import org.eclipse.jface.text.IDocument;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.texteditor.ITextEditor;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.python.pydev.ast.interpreter_managers.InterpreterManagersAPI;
import org.python.pydev.debug.core.Constants;
import org.python.pydev.debug.model.PyBreakpoint;
import org.python.pydev.debug.ui.actions.PyBreakpointRulerAction;
import org.python.pydev.debug.ui.launching.RegularLaunchConfigurationDelegate;
import org.python.pydev.editor.PyEdit;
import org.python.pydev.plugin.nature.PythonNature;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;
import org.stagecraft.tools.session.Ports;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.PythonClientPath;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionParts;

/**
 * Robot Sessions with the real PyDev (13.1.0, installed into this test runtime by p2 from its
 * archived update site) and a python3 configured in PyDev the way PyDev's interpreter preference
 * page does it (PyDev runs its own pysrc/interpreterInfo.py). Player is the stand-in Player of
 * org.stagecraft.tools.tests, serving a recorded Player conversation.
 */
// PyDev logs its first analysis of a new project as an ERROR ("Info: Rebuilding internal caches"): PyDev's, not ours; and its "Module resolved" job fails on this test's project whose own root is its source folder
@LogsErrors({ "^org\\.python\\.pydev\\.shared_core: Info: Rebuilding internal caches", "Module resolved: extlib_mod.*Path must include project and resource name",
        // PyDev's late analysis of PyDevRobotProjectTest's "Existing" project (the class before this one)
        "^org\\.python\\.pydev\\.shared_core: .*/Existing\\b" })
@Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class PyDevRobotSessionTest {
    private static final Duration WAIT = Duration.ofSeconds(60);
    private static final String TRACE = "pioneer-laser-sonar.gt.trace.jsonl";
    private static String python;

    private final List<ILaunch> launches = new ArrayList<>();
    private Path tmp;
    private IProject project;
    private Path externalLibrary;

    @BeforeAll
    static void pyDevWithPython3() throws Exception {
        python = PyDevInterpreter.onPath("python3");
        PyDevInterpreter.configure(python);
    }

    @BeforeEach
    void setUp() throws Exception {
        tmp = Files.createTempDirectory("stagecraft-pydev-test");
        externalLibrary = Files.createDirectories(tmp.resolve("external-lib"));
        Files.writeString(externalLibrary.resolve("extlib_mod.py"), "VALUE = 'from-external-library'\n");
        project = pyDevProjectWithWorlds("robot-pydev-" + System.nanoTime(), externalLibrary);
    }

    @AfterEach
    void tearDown() throws Exception {
        for (ILaunch l : launches) {
            if (!l.isTerminated()) {
                l.terminate();
            }
            DebugPlugin.getDefault().getLaunchManager().removeLaunch(l);
        }
        DebugPlugin.getDefault().getBreakpointManager().removeBreakpoints(
                DebugPlugin.getDefault().getBreakpointManager().getBreakpoints(), true);
        Display.getDefault().syncExec(() -> PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage().closeAllEditors(false));
        project.delete(true, true, new NullProgressMonitor());
    }

    // ------------------------------------------------------------------------------------------

    @Test
    void theIdsStagecraftUsesForPyDevAreThoseOfTheInstalledPyDev() throws Exception {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationType type = lm.getLaunchConfigurationType(LaunchAttributes.PYDEV_RUN_TYPE);
        assertNotNull(type, "PyDev has a launch configuration type " + LaunchAttributes.PYDEV_RUN_TYPE);
        assertInstanceOf(RegularLaunchConfigurationDelegate.class, type.getDelegates(Set.of(ILaunchManager.RUN_MODE))[0].getDelegate(),
                "it is PyDev's Python Run");
        assertTrue(type.supportsMode(ILaunchManager.DEBUG_MODE));
        assertEquals(Constants.ATTR_PROJECT, LaunchAttributes.PYDEV_PROJECT);
        assertEquals(Constants.ATTR_LOCATION, LaunchAttributes.EXTERNAL_TOOLS_LOCATION);
        assertEquals(Constants.ATTR_WORKING_DIRECTORY, LaunchAttributes.EXTERNAL_TOOLS_WORKING_DIRECTORY);
        assertEquals(PythonNature.PYTHON_NATURE_ID, LaunchAttributes.PYDEV_NATURE);
        assertTrue(project.hasNature(LaunchAttributes.PYDEV_NATURE), "PyDev's nature id is the one Stagecraft checks");
        // the bundles a session calls PyDev's public API in (by reflection: PyDev is optional)
        assertEquals(LaunchAttributes.PYDEV_DEBUG_BUNDLE,
                org.osgi.framework.FrameworkUtil.getBundle(org.python.pydev.debug.ui.launching.PythonRunnerConfig.class).getSymbolicName());
        assertEquals(LaunchAttributes.PYDEV_AST_BUNDLE,
                org.osgi.framework.FrameworkUtil.getBundle(InterpreterManagersAPI.class).getSymbolicName());
        // where PyDev keeps its interpreters (what a pre-seeded workspace sets): INTERPRETER_PATH_NEW
        String persisted = InstanceScope.INSTANCE.getNode("org.python.pydev").get("INTERPRETER_PATH_NEW", "");
        assertTrue(persisted.contains(python), "INTERPRETER_PATH_NEW of org.python.pydev holds " + python + ": " + persisted);
    }

    @Test
    void aSessionRunsItsProgramAsPyDevsPythonRunInsideTheSessionOnPyDevsPathAndEndsIt() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        Path result = tmp.resolve("result.txt");
        IFile robot = write(project, "robot.py", """
                import importlib.util, os, socket, sys, threading
                import extlib_mod
                client = importlib.util.find_spec("stagecraft_player")  # importing it needs pint
                s = socket.create_connection(("127.0.0.1", int(os.environ["ROBOT_PORT"])))
                banner = b""
                while len(banner) < 32:
                    chunk = s.recv(32 - len(banner))
                    if not chunk:
                        break
                    banner += chunk
                s.close()
                out = os.environ["RESULT"]
                with open(out + ".tmp", "w") as f:
                    f.write("pid\\t%d\\n" % os.getpid())
                    f.write("banner\\t%s\\n" % banner.rstrip(b"\\0").decode())
                    f.write("ext\\t%s\\n" % extlib_mod.VALUE)
                    f.write("client\\t%s\\n" % os.path.dirname(os.path.dirname(os.path.abspath(client.origin))))
                    f.write("pythonpath\\t%s\\n" % os.environ.get("PYTHONPATH", ""))
                os.rename(out + ".tmp", out)
                threading.Event().wait()  # a robot program runs until it is stopped
                """);
        ILaunchConfigurationWorkingCopy wc = config(port, robot, Map.of("ROBOT_PORT", String.valueOf(port), "RESULT", result.toString()));
        Set<ILaunch> before = Set.of(DebugPlugin.getDefault().getLaunchManager().getLaunches());

        ILaunch launch = launch(wc, ILaunchManager.RUN_MODE);
        IProcess program = programOf(launch);
        assertEquals(Constants.PROCESS_TYPE, program.getAttribute(IProcess.ATTR_PROCESS_TYPE), "PyDev's Python process");
        assertEquals("PYDEV.PYTHON", program.getAttribute(IProcess.ATTR_PROCESS_TYPE));
        assertTrue(program.getAttribute(IProcess.ATTR_CMDLINE).contains(robot.getLocation().toOSString()),
                program.getAttribute(IProcess.ATTR_CMDLINE));
        List<ILaunch> added = Arrays.stream(DebugPlugin.getDefault().getLaunchManager().getLaunches())
                .filter(l -> !before.contains(l)).toList();
        assertEquals(List.of(launch), added, "one launch in the Debug view: the Robot Session, owning its program");

        Map<String, String> seen = awaitResult(result, program);
        assertTrue(seen.get("banner").startsWith("Player"), "the program talked to Player through the spy: " + seen);
        assertEquals("from-external-library", seen.get("ext"), "a module of a PyDev external library imports");
        Optional<String> client = PythonClientPath.folder();
        assertTrue(client.isPresent());
        assertEquals(Path.of(client.get()).toRealPath(), Path.of(seen.get("client")).toRealPath(), "stagecraft_player is found");
        List<String> path = List.of(seen.get("pythonpath").split(File.pathSeparator));
        assertTrue(path.contains(externalLibrary.toString()), "PyDev's external library is on PYTHONPATH: " + path);
        assertTrue(path.contains(project.getLocation().toOSString()), "PyDev's source folder is on PYTHONPATH: " + path);
        assertTrue(path.stream().anyMatch(p -> p.endsWith("pydev_sitecustomize")), "PyDev's sitecustomize is on PYTHONPATH: " + path);
        // after PyDev's own entries for the project, once: appended by the session, or named by the project itself
        // (projects.ui makes a session's project a robot project for PyDev, RobotSessionProjects, in a job of its own
        // that may come before the program starts)
        assertTrue(path.indexOf(client.get()) > path.indexOf(externalLibrary.toString()),
                "the client's folder comes after PyDev's path for the project: " + path);
        assertEquals(1, path.stream().filter(client.get()::equals).count(), "the client's folder once: " + path);

        long pid = Long.parseLong(seen.get("pid"));
        try (DebugEvents events = new DebugEvents()) {
            launch.terminate();
            events.await("the program's process to end with the session", WAIT,
                    e -> e.getSource() == program && e.getKind() == DebugEvent.TERMINATE);
        }
        Await.until("the whole session to end (Player and the spy stop in the background)", WAIT, launch::isTerminated,
                () -> Arrays.stream(launch.getProcesses()).map(p -> p.getLabel() + " terminated=" + p.isTerminated()).toList().toString());
        Await.until("the program's OS process " + pid + " to be gone", WAIT,
                () -> ProcessHandle.of(pid).map(h -> !h.isAlive()).orElse(true), () -> "");
    }

    @Test
    void whenTheProgramIsTerminatedItsEndShowsInTheSessionAndTheSessionStopsWhenAsked() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        Path result = tmp.resolve("result.txt");
        IFile robot = write(project, "robot.py", """
                import os, threading
                with open(os.environ["RESULT"], "w") as f:
                    f.write("pid\\t%d\\n" % os.getpid())
                threading.Event().wait()
                """);
        ILaunch launch = launch(config(port, robot, Map.of("RESULT", result.toString())), ILaunchManager.RUN_MODE);
        IProcess program = programOf(launch);
        awaitResult(result, program);
        SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
        try (DebugEvents events = new DebugEvents()) {
            program.terminate();
            events.await("the program's process to end", WAIT, e -> e.getSource() == program && e.getKind() == DebugEvent.TERMINATE);
        }
        assertTrue(Arrays.asList(launch.getProcesses()).contains(program), "the ended program is still shown in its session");
        assertTrue(program.isTerminated());
        // the rest of the session (Player, spy) runs on until the session is terminated
        assertFalse(launch.isTerminated());
        assertTrue(parts.session().player().process().isAlive());
        ProcessHandle player = parts.session().player().process();
        try (DebugEvents events = new DebugEvents()) {
            launch.terminate();
            events.await("the session to end", WAIT, e -> e.getSource() instanceof IProcess p && p.getLaunch() == launch
                    && e.getKind() == DebugEvent.TERMINATE && launch.isTerminated());
        }
        Await.until("Player to be gone", WAIT, () -> !player.isAlive(), () -> "");
    }

    @Test
    void debugAsRobotSessionStopsAtAPyDevLineBreakpointAndResumeLetsTheProgramFinish() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        Path result = tmp.resolve("result.txt");
        IFile robot = write(project, "robot.py", """
                import os
                x = 20
                y = x + 1
                with open(os.environ["RESULT"], "w") as f:
                    f.write("y\\t%d\\n" % y)
                """);
        int line = 3;
        IBreakpoint breakpoint = breakpointAsPyDevsRulerMakesIt(robot, line);
        assertEquals(PyBreakpoint.PY_BREAK_MARKER, breakpoint.getMarker().getType());
        assertEquals(line, breakpoint.getMarker().getAttribute(IMarker.LINE_NUMBER, -1));

        ILaunchConfigurationWorkingCopy wc = config(port, robot, Map.of("RESULT", result.toString()));
        try (DebugEvents events = new DebugEvents()) {
            ILaunch launch = launch(wc, ILaunchManager.DEBUG_MODE);
            IProcess program = programOf(launch);
            assertTrue(program.getAttribute(IProcess.ATTR_CMDLINE).contains("pydevd.py"),
                    "the program runs under pydevd: " + program.getAttribute(IProcess.ATTR_CMDLINE));
            DebugEvent suspend = events.await("a thread suspended at the breakpoint", WAIT,
                    e -> e.getKind() == DebugEvent.SUSPEND && e.getDetail() == DebugEvent.BREAKPOINT && e.getSource() instanceof IThread);
            IThread thread = (IThread) suspend.getSource();
            assertSame(launch, thread.getLaunch(), "the debug target is part of the Robot Session's launch");
            AtomicReference<Integer> at = new AtomicReference<>();
            at.set(thread.getTopStackFrame().getLineNumber());
            assertEquals(line, at.get(), "suspended at the breakpoint's line");
            assertFalse(Files.exists(result), "suspended before the program wrote its result");

            thread.resume();
            events.await("the thread to resume", WAIT, e -> e.getSource() == thread && e.getKind() == DebugEvent.RESUME);
            events.await("the program to finish", WAIT, e -> e.getSource() == program && e.getKind() == DebugEvent.TERMINATE);
            assertEquals(0, program.getExitValue());
            assertEquals("21", awaitResult(result, program).get("y"));
        }
    }

    @Test
    void terminatingTheSessionWhileItsProgramIsSuspendedEndsAllOfIt() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        IFile robot = write(project, "robot.py", """
                x = 1
                y = x + 1
                print(y)
                """);
        breakpointAsPyDevsRulerMakesIt(robot, 2);
        try (DebugEvents events = new DebugEvents()) {
            ILaunch launch = launch(config(port, robot, Map.of()), ILaunchManager.DEBUG_MODE);
            IProcess program = programOf(launch);
            events.await("a thread suspended at the breakpoint", WAIT,
                    e -> e.getKind() == DebugEvent.SUSPEND && e.getDetail() == DebugEvent.BREAKPOINT && e.getSource() instanceof IThread);
            ProcessHandle player = RobotSessionLaunchDelegate.partsOf(launch).session().player().process();
            launch.terminate();
            events.await("the program to end", WAIT, e -> e.getSource() == program && e.getKind() == DebugEvent.TERMINATE);
            Await.until("the whole session to end", WAIT, launch::isTerminated, () -> Arrays.stream(launch.getProcesses())
                    .map(p -> p.getLabel() + " terminated=" + p.isTerminated()).toList() + " targets "
                    + Arrays.stream(launch.getDebugTargets()).map(t -> t + " terminated=" + t.isTerminated()).toList());
            Await.until("Player to be gone", WAIT, () -> !player.isAlive(), () -> "");
        }
    }

    // ------------------------------------------------------------------------------------------

    /** A line breakpoint set the way PyDev's editor ruler sets one (PyDev's own code), in PyDev's editor. */
    private static IBreakpoint breakpointAsPyDevsRulerMakesIt(IFile file, int line) throws Exception {
        AtomicReference<Object> editorClass = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                IEditorPart editor = IDE.openEditor(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage(), file);
                editorClass.set(editor);
                ITextEditor text = (ITextEditor) editor;
                IDocument doc = text.getDocumentProvider().getDocument(text.getEditorInput());
                PyBreakpointRulerAction.addBreakpointMarker(doc, line, text, PyBreakpoint.PY_BREAK_TYPE_PYTHON);
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        assertInstanceOf(PyEdit.class, editorClass.get(), ".py files open in PyDev's editor");
        IBreakpoint[] all = DebugPlugin.getDefault().getBreakpointManager().getBreakpoints();
        List<IBreakpoint> mine = Arrays.stream(all).filter(b -> b.getMarker() != null && file.equals(b.getMarker().getResource())).toList();
        assertEquals(1, mine.size(), "one breakpoint in " + file + ": " + Arrays.toString(all));
        return mine.get(0);
    }

    private ILaunchConfigurationWorkingCopy config(int port, IFile program, Map<String, String> env) throws CoreException {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null,
                lm.generateLaunchConfigurationName("pydev-session"));
        wc.setAttribute(LaunchAttributes.CFG, project.getFile("worlds/pioneer-laser-sonar.cfg").getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, standIn());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of("STANDIN_TRACE", WorldsProject.traces().resolve(TRACE).toString()));
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, port);
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "");
        wc.setAttribute(LaunchAttributes.TOOLS, List.<String>of());
        wc.setAttribute(LaunchAttributes.PROGRAM, program.getFullPath().toString());
        wc.setAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, new HashMap<>(env));
        return wc;
    }

    private ILaunch launch(ILaunchConfigurationWorkingCopy wc, String mode) throws CoreException {
        ILaunch l = wc.launch(mode, new NullProgressMonitor());
        launches.add(l);
        return l;
    }

    /** The robot program's process in the session's launch: the one PyDev made (it has PyDev's process attributes). */
    private static IProcess programOf(ILaunch launch) {
        return Arrays.stream(launch.getProcesses()).filter(p -> p.getAttribute(Constants.PYDEV_CONFIG_RUN) != null).findFirst()
                .orElseThrow(() -> new AssertionError("no process started by PyDev in the session: "
                        + Arrays.stream(launch.getProcesses()).map(p -> p.getLabel() + " " + p.getAttribute(IProcess.ATTR_PROCESS_TYPE)).toList()));
    }

    private static Map<String, String> awaitResult(Path result, IProcess program) throws IOException {
        Await.until("the robot program wrote " + result, WAIT, () -> Files.exists(result), () -> "; program terminated: "
                + program.isTerminated() + ", its output:\n" + program.getStreamsProxy().getOutputStreamMonitor().getContents()
                + "\nits errors:\n" + program.getStreamsProxy().getErrorStreamMonitor().getContents());
        Map<String, String> m = new HashMap<>();
        for (String l : Files.readAllLines(result)) {
            String[] kv = l.split("\t", 2);
            m.put(kv[0], kv.length > 1 ? kv[1] : "");
        }
        return m;
    }

    private static String standIn() {
        String s = System.getProperty("stagecraft.standin");
        assertNotNull(s, "-Dstagecraft.standin (the stand-in Player of org.stagecraft.tools.tests)");
        assertTrue(Files.isRegularFile(Path.of(s)), s);
        return s;
    }

    /** A PyDev project (source folder: the project; one external library) holding a copy of tests/traces/worlds. */
    private static IProject pyDevProjectWithWorlds(String name, Path externalLibrary) throws Exception {
        IProject p = WorldsProject.create(name, externalLibrary);
        assertTrue(p.hasNature(PythonNature.PYTHON_NATURE_ID));
        return p;
    }

    private static IFile write(IProject p, String path, String text) throws CoreException, IOException {
        Path file = p.getLocation().toPath().resolve(path);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        p.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());
        return p.getFile(path);
    }
}
