package org.stagecraft.projects.ui;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Optional;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Path;
import org.eclipse.core.runtime.Status;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchesListener2;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.IStartup;
import org.stagecraft.projects.ui.layout.PyDevProjectFile;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.PythonClientPath;

/**
 * Every project a Robot Session runs a program from becomes a robot project for PyDev (when PyDev is
 * installed): without it PyDev's code analysis marks {@code from stagecraft_player import ...} as
 * unresolved, although the session's program finds the client. Projects made by the New Robot Project
 * wizard are configured already; this covers projects a user made by hand and launched with Run As >
 * Robot Session (from the shortcut or a launch configuration). The change is made in a job of its own
 * after the launch was added, never inside the launch (adding a nature takes the workspace root).
 */
public final class RobotSessionProjects implements IStartup, ILaunchesListener2 {

    @Override
    public void earlyStartup() {
        if (RobotProjects.pyDevInstalled()) {
            DebugPlugin.getDefault().getLaunchManager().addLaunchListener(this);
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void launchesAdded(ILaunch[] launches) {
        for (ILaunch launch : launches) {
            IProject project = robotProject(launch.getLaunchConfiguration());
            if (project != null && !configured(project)) {
                configureLater(project);
            }
        }
    }

    /** The project of the session's program (or of its cfg when no program is set); null for other launches. */
    public static @Nullable IProject robotProject(@Nullable ILaunchConfiguration config) {
        try {
            if (config == null || !LaunchAttributes.TYPE.equals(config.getType().getIdentifier())) {
                return null;
            }
            String where = config.getAttribute(LaunchAttributes.PROGRAM, "");
            if (where.isBlank()) {
                where = config.getAttribute(LaunchAttributes.CFG, "");
            }
            if (where.isBlank() || !where.startsWith("/")) {
                return null;
            }
            IResource r = ResourcesPlugin.getWorkspace().getRoot().findMember(new Path(where));
            return r == null || !r.getProject().isOpen() ? null : r.getProject();
        } catch (CoreException e) {
            return null;
        }
    }

    /** PyDev nature there and the client folder named in its {@code .pydevproject}. */
    public static boolean configured(IProject project) {
        try {
            if (!project.hasNature(RobotProjects.PYDEV_NATURE)) {
                return false;
            }
            Optional<String> folder = PythonClientPath.folder();
            if (folder.isEmpty()) {
                return true; // nothing Stagecraft could add
            }
            String client = folder.get();
            IFile file = project.getFile(PyDevProjectFile.FILE_NAME);
            if (!file.exists()) {
                return false;
            }
            try (InputStream in = file.getContents(true)) {
                return new String(in.readAllBytes(), StandardCharsets.UTF_8).contains(client);
            }
        } catch (CoreException | IOException e) {
            return false;
        }
    }

    private static void configureLater(IProject project) {
        WorkspaceJob job = new WorkspaceJob("Making " + project.getName() + " a robot project for PyDev") {
            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
                RobotProjects.configurePyDev(project, monitor);
                return Status.OK_STATUS;
            }
        };
        job.setRule(ResourcesPlugin.getWorkspace().getRoot());
        job.setSystem(true);
        job.schedule();
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void launchesTerminated(ILaunch[] launches) {
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void launchesRemoved(ILaunch[] launches) {
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void launchesChanged(ILaunch[] launches) {
    }
}
