package org.stagecraft.tools.ui.launch;

import java.util.Arrays;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.ui.DebugUITools;
import org.eclipse.debug.ui.ILaunchShortcut;
import org.eclipse.jface.viewers.ISelection;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.ui.IEditorPart;

/**
 * Run As &gt; Robot Session on a {@code .cfg} file: reuses the configuration made for that file, or
 * creates one (with the only {@code .py} file beside the cfg as the robot program, if there is
 * exactly one).
 */
public final class RobotSessionShortcut implements ILaunchShortcut {

    @Override
    public void launch(ISelection selection, String mode) {
        if (selection instanceof IStructuredSelection s && s.getFirstElement() instanceof IAdaptable a) {
            IFile f = a.getAdapter(IFile.class);
            if (f != null) {
                launch(f, mode);
            }
        }
    }

    @Override
    public void launch(IEditorPart editor, String mode) {
        IFile f = editor.getEditorInput().getAdapter(IFile.class);
        if (f != null) {
            launch(f, mode);
        }
    }

    private static void launch(IFile cfg, String mode) {
        try {
            DebugUITools.launch(configurationFor(cfg), mode);
        } catch (CoreException e) {
            SessionParts.log(e.getStatus());
        }
    }

    /** The Robot Session configuration of {@code cfg}, made and saved if there is none yet. */
    public static ILaunchConfiguration configurationFor(IFile cfg) throws CoreException {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationType type = lm.getLaunchConfigurationType(LaunchAttributes.TYPE);
        String path = cfg.getFullPath().toString();
        for (ILaunchConfiguration c : lm.getLaunchConfigurations(type)) {
            if (path.equals(c.getAttribute(LaunchAttributes.CFG, ""))) {
                return c;
            }
        }
        ILaunchConfigurationWorkingCopy wc = type.newInstance(null, lm.generateLaunchConfigurationName(
                cfg.getName().replaceFirst("\\.cfg$", "")));
        new RobotSessionTab().setDefaults(wc);
        wc.setAttribute(LaunchAttributes.CFG, path);
        IResource[] pys = Arrays.stream(cfg.getParent().members())
                .filter(r -> r instanceof IFile && "py".equals(r.getFileExtension())).toArray(IResource[]::new);
        if (pys.length == 1) {
            wc.setAttribute(LaunchAttributes.PROGRAM, pys[0].getFullPath().toString());
        }
        wc.setMappedResources(new IResource[] {cfg});
        return wc.doSave();
    }
}
