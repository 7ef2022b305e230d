package org.stagecraft.tools.ui.launch;

import java.io.File;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchDelegate;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.core.model.IProcess;
import org.eclipse.core.runtime.Status;
import org.eclipse.jdt.annotation.Nullable;
import org.osgi.framework.Bundle;
import org.stagecraft.tools.ui.prefs.ToolPreferences;

/**
 * Starts the robot program, unchanged, once Player and the spy run. With PyDev installed (detected
 * at run time by its launch configuration type id) PyDev's own "Python Run" launcher starts it as a
 * part of the session's launch, so running and debugging work as PyDev users expect, and the user
 * sees one Robot Session that owns its program. Without PyDev, the configured interpreter runs it as a process of the session's launch.
 * Either way the program finds Stagecraft's Python Player client on its PYTHONPATH
 * ({@link PythonClientPath}), added to what is there (PyDev's computed path included), never
 * replacing it.
 */
final class RobotProgram {
    private RobotProgram() {
    }

    static boolean pyDevInstalled() {
        return DebugPlugin.getDefault().getLaunchManager().getLaunchConfigurationType(LaunchAttributes.PYDEV_RUN_TYPE) != null;
    }

    static void start(ILaunchConfiguration config, String mode, ILaunch launch, SessionSettings s, SessionParts parts,
            IProgressMonitor monitor) throws CoreException {
        IFile program = s.program();
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationType pydev = lm.getLaunchConfigurationType(LaunchAttributes.PYDEV_RUN_TYPE);
        if (pydev != null) {
            int partsBefore = launch.getProcesses().length;
            try {
                if (program.getProject().hasNature(LaunchAttributes.PYDEV_NATURE)) {
                    startWithPyDev(pydev, config, mode, launch, program, lm, monitor);
                    ProgramPart.follow(parts, program.getName(), launch.getProcesses()[partsBefore]);
                    return;
                }
                SessionParts.log(Status.warning(program.getProject().getName() + " is not a PyDev project (no "
                        + LaunchAttributes.PYDEV_NATURE + " nature): " + program.getName()
                        + " runs with the plain interpreter instead"));
            } catch (CoreException e) {
                if (launch.isTerminated() || launch.getProcesses().length > partsBefore) {
                    // PyDev gave up on the launch itself (and said why), or failed after starting the
                    // program (e.g. pydevd did not connect): no second start with the plain interpreter
                    throw e;
                }
                SessionParts.log(Status.warning("PyDev could not launch " + program.getFullPath()
                        + "; running it with the plain interpreter", e));
            }
        }
        String python = ToolPreferences.get(ToolPreferences.PYTHON);
        String[] env = withClientPath(lm.getEnvironment(config), lm);
        File dir = program.getParent().getLocation().toFile();
        Process p = DebugPlugin.exec(new String[] {python, program.getLocation().toOSString()}, dir, env);
        IProcess process = DebugPlugin.newProcess(launch, p, program.getName() + " (" + python + ")",
                Map.of(IProcess.ATTR_PROCESS_TYPE, "python"));
        ProgramPart.follow(parts, program.getName(), process);
    }

    /**
     * The program as PyDev's "Python Run", inside the session's own launch: PyDev's launch delegate
     * is given the session's {@link ILaunch}, so the program's process (and in debug mode PyDev's
     * debug target) is one more part of the Robot Session in the Debug view, ends when the session
     * is terminated, and shows there as ended when it ends. The configuration is a working copy
     * that is never saved.
     */
    private static void startWithPyDev(ILaunchConfigurationType pydev, ILaunchConfiguration config, String mode,
            ILaunch launch, IFile program, ILaunchManager lm, IProgressMonitor monitor) throws CoreException {
        ILaunchConfigurationWorkingCopy wc = pydev.newInstance(null,
                lm.generateLaunchConfigurationName(config.getName() + " - " + program.getName()));
        wc.setAttribute(LaunchAttributes.EXTERNAL_TOOLS_LOCATION, "${workspace_loc:" + program.getFullPath() + "}");
        wc.setAttribute(LaunchAttributes.EXTERNAL_TOOLS_WORKING_DIRECTORY,
                "${workspace_loc:" + program.getParent().getFullPath() + "}");
        wc.setAttribute(LaunchAttributes.PYDEV_PROJECT, program.getProject().getName());
        Map<String, String> env = config.getAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, Map.of());
        boolean append = config.getAttribute(ILaunchManager.ATTR_APPEND_ENVIRONMENT_VARIABLES, true);
        wc.setAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, env);
        wc.setAttribute(ILaunchManager.ATTR_APPEND_ENVIRONMENT_VARIABLES, append);
        wc.setAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, withClientPathForPyDev(wc, env));
        ILaunchDelegate[] delegates = pydev.getDelegates(Set.of(mode));
        if (delegates.length == 0) {
            throw new CoreException(Status.error("PyDev has no launcher for mode " + mode));
        }
        int before = launch.getProcesses().length;
        try {
            delegates[0].getDelegate().launch(wc, mode, launch, monitor);
        } catch (RuntimeException e) {
            // the session must still be stopped (it is, for a CoreException)
            throw new CoreException(Status.error("PyDev failed to launch " + program.getFullPath() + ": " + e, e));
        }
        if (launch.getProcesses().length == before) {
            throw new CoreException(Status.error("PyDev did not start " + program.getFullPath()
                    + " (see its message and the Error Log)"));
        }
    }

    /**
     * PyDev puts its own PYTHONPATH (PyDev's sitecustomize, the project's source folders and
     * external libraries, the interpreter's libraries) on a program only when the launch does not
     * set PYTHONPATH itself. So the client's folder is appended to the path PyDev computes for this
     * configuration (PyDev's public {@code PythonRunnerConfig.getPythonpathFromConfiguration}), or,
     * if the Robot Session's environment sets PYTHONPATH (which replaces PyDev's, as in any PyDev
     * launch), to that. If PyDev's path cannot be had, PYTHONPATH is left to PyDev.
     */
    private static Map<String, String> withClientPathForPyDev(ILaunchConfiguration wc, Map<String, String> env) {
        Optional<String> folder = PythonClientPath.folder();
        if (folder.isEmpty()) {
            return env;
        }
        @Nullable String base = env.get(PythonClientPath.VARIABLE);
        if (base == null) {
            try {
                base = pyDevPythonpath(wc);
            } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
                Throwable cause = e instanceof java.lang.reflect.InvocationTargetException ite && ite.getCause() != null
                        ? ite.getCause() : e;
                SessionParts.log(Status.warning("cannot get PyDev's PYTHONPATH for " + wc.getName() + " (" + cause
                        + "): the program's PYTHONPATH is left to PyDev and lacks " + folder.get(), cause));
                return env;
            }
        }
        Map<String, String> out = new LinkedHashMap<>(env);
        out.put(PythonClientPath.VARIABLE, PythonClientPath.append(base, folder.get()));
        return out;
    }

    /** What PyDev itself would set as PYTHONPATH for {@code wc}; PyDev is optional, so by reflection. */
    private static String pyDevPythonpath(ILaunchConfiguration wc) throws ReflectiveOperationException {
        Class<?> runnerConfig = pyDevClass(LaunchAttributes.PYDEV_DEBUG_BUNDLE, "org.python.pydev.debug.ui.launching.PythonRunnerConfig");
        Class<?> managers = pyDevClass(LaunchAttributes.PYDEV_AST_BUNDLE, "org.python.pydev.ast.interpreter_managers.InterpreterManagersAPI");
        Object manager = managers.getMethod("getPythonInterpreterManager").invoke(null);
        for (Method m : runnerConfig.getMethods()) {
            if (m.getName().equals("getPythonpathFromConfiguration") && m.getParameterCount() == 2
                    && Modifier.isStatic(m.getModifiers())) {
                return (String) m.invoke(null, wc, manager);
            }
        }
        throw new NoSuchMethodException(runnerConfig.getName() + ".getPythonpathFromConfiguration");
    }

    private static Class<?> pyDevClass(String bundle, String name) throws ClassNotFoundException {
        Bundle b = Platform.getBundle(bundle);
        if (b == null) {
            throw new ClassNotFoundException(name + " (bundle " + bundle + " is not installed)");
        }
        return b.loadClass(name);
    }

    /** The same for the plain interpreter: {@code env} is null when the launch inherits everything. */
    private static String @Nullable [] withClientPath(String @Nullable [] env, ILaunchManager lm) {
        Optional<String> folder = PythonClientPath.folder();
        if (folder.isEmpty()) {
            return env;
        }
        List<String> out = new ArrayList<>();
        if (env == null) {
            lm.getNativeEnvironmentCasePreserved().forEach((k, v) -> out.add(k + "=" + v));
        } else {
            out.addAll(Arrays.asList(env));
        }
        String prefix = PythonClientPath.VARIABLE + "=";
        int at = -1;
        for (int i = 0; i < out.size(); i++) {
            if (out.get(i).startsWith(prefix)) {
                at = i;
            }
        }
        if (at < 0) {
            out.add(prefix + folder.get());
        } else {
            out.set(at, prefix + PythonClientPath.append(out.get(at).substring(prefix.length()), folder.get()));
        }
        return out.toArray(String[]::new);
    }
}
