package org.stagecraft.tools.ui.launch;

import java.io.File;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.core.model.IProcess;
import org.eclipse.core.runtime.Status;
import org.stagecraft.tools.ui.prefs.ToolPreferences;

/**
 * Starts the robot program, unchanged, once Player and the spy run. With PyDev installed (detected
 * at run time by its launch configuration type id) it becomes PyDev's own "Python Run" launch, so
 * running and debugging work as PyDev users expect; that launch is linked to the session and ends
 * with it. Without PyDev, the configured interpreter runs it as a process of the session's launch.
 * Either way the program finds Stagecraft's Python Player client on its PYTHONPATH
 * ({@link PythonClientPath}).
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
            try {
                if (program.getProject().hasNature(LaunchAttributes.PYDEV_NATURE)) {
                    ILaunchConfigurationWorkingCopy wc = pydev.newInstance(null,
                            lm.generateLaunchConfigurationName(config.getName() + " - " + program.getName()));
                    wc.setAttribute(LaunchAttributes.EXTERNAL_TOOLS_LOCATION, "${workspace_loc:" + program.getFullPath() + "}");
                    wc.setAttribute(LaunchAttributes.EXTERNAL_TOOLS_WORKING_DIRECTORY,
                            "${workspace_loc:" + program.getParent().getFullPath() + "}");
                    wc.setAttribute(LaunchAttributes.PYDEV_PROJECT, program.getProject().getName());
                    Map<String, String> env = config.getAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, Map.of());
                    boolean append = config.getAttribute(ILaunchManager.ATTR_APPEND_ENVIRONMENT_VARIABLES, true);
                    wc.setAttribute(ILaunchManager.ATTR_ENVIRONMENT_VARIABLES, withClientPath(env, append, lm));
                    wc.setAttribute(ILaunchManager.ATTR_APPEND_ENVIRONMENT_VARIABLES, append);
                    parts.link(wc.launch(mode, monitor));
                    return;
                }
                SessionParts.log(Status.warning(program.getProject().getName() + " is not a PyDev project (no "
                        + LaunchAttributes.PYDEV_NATURE + " nature): " + program.getName()
                        + " runs with the plain interpreter instead"));
            } catch (CoreException e) {
                SessionParts.log(Status.warning("PyDev could not launch " + program.getFullPath()
                        + "; running it with the plain interpreter", e));
            }
        }
        String python = ToolPreferences.get(ToolPreferences.PYTHON);
        String[] env = withClientPath(lm.getEnvironment(config), lm);
        File dir = program.getParent().getLocation().toFile();
        Process p = DebugPlugin.exec(new String[] {python, program.getLocation().toOSString()}, dir, env);
        DebugPlugin.newProcess(launch, p, program.getName() + " (" + python + ")",
                Map.of(IProcess.ATTR_PROCESS_TYPE, "python"));
    }

    /**
     * The launch's environment variables with the Python client's folder appended to PYTHONPATH
     * (to the configuration's own PYTHONPATH, else to the inherited one when the configuration
     * appends to the native environment).
     */
    private static Map<String, String> withClientPath(Map<String, String> env, boolean append, ILaunchManager lm) {
        Optional<String> folder = PythonClientPath.folder();
        if (folder.isEmpty()) {
            return env;
        }
        Map<String, String> out = new LinkedHashMap<>(env);
        String existing = env.get(PythonClientPath.VARIABLE);
        if (existing == null && append) {
            existing = lm.getNativeEnvironmentCasePreserved().get(PythonClientPath.VARIABLE);
        }
        out.put(PythonClientPath.VARIABLE, PythonClientPath.append(existing, folder.get()));
        return out;
    }

    /** The same for the plain interpreter: {@code env} is null when the launch inherits everything. */
    private static String[] withClientPath(String[] env, ILaunchManager lm) {
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
