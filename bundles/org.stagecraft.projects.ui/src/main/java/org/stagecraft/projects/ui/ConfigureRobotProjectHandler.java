package org.stagecraft.projects.ui;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.Adapters;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.MultiStatus;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.ErrorDialog;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.jface.viewers.ISelection;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.handlers.HandlerUtil;

/**
 * Configure &gt; Configure as Robot Project on projects: {@link RobotProjects#configurePyDev} for each,
 * or a message saying PyDev is needed.
 */
public final class ConfigureRobotProjectHandler extends AbstractHandler {
    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) throws ExecutionException {
        Shell shell = HandlerUtil.getActiveShell(event);
        List<IProject> projects = projects(HandlerUtil.getCurrentSelection(event));
        if (projects.isEmpty()) {
            return null;
        }
        if (!RobotProjects.pyDevInstalled()) {
            MessageDialog.openInformation(shell, "Configure as Robot Project",
                    "PyDev (" + RobotProjects.PYDEV_BUNDLE + ") is not installed. Robot Sessions still run the "
                            + "projects' programs with the Python interpreter of the Stagecraft Tools preferences; install "
                            + "PyDev for a Python editor with code analysis, completion and the debugger.");
            return null;
        }
        MultiStatus problems = new MultiStatus(RobotProjects.BUNDLE, 0, "Some projects could not be configured");
        for (IProject p : projects) {
            try {
                RobotProjects.configurePyDev(p);
            } catch (CoreException e) {
                problems.add(e.getStatus());
            }
        }
        if (!problems.isOK()) {
            ErrorDialog.openError(shell, "Configure as Robot Project", null, problems);
        }
        return null;
    }

    /** The open projects of a selection (of projects or anything in them). */
    static List<IProject> projects(ISelection selection) {
        List<IProject> out = new ArrayList<>();
        if (selection instanceof IStructuredSelection s) {
            for (Object o : s.toList()) {
                @Nullable IResource r = Adapters.adapt(o, IResource.class);
                if (r != null && r.getProject() != null && r.getProject().isOpen() && !out.contains(r.getProject())) {
                    out.add(r.getProject());
                }
            }
        }
        return out;
    }

}
