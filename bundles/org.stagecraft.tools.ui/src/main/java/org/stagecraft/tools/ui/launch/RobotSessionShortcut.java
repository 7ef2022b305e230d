package org.stagecraft.tools.ui.launch;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.core.runtime.Status;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.ui.DebugUITools;
import org.eclipse.debug.ui.ILaunchShortcut;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.viewers.ISelection;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.PlatformUI;

/**
 * Run As &gt; Robot Session on a {@code .cfg} file: reuses the configuration made for that file, or
 * creates one (with the only {@code .py} file beside the cfg as the robot program, if there is
 * exactly one). On a {@code .py} file (the robot program): reuses the configuration that runs it,
 * or creates one with the only {@code .cfg} beside it, else the only one in its project; with none
 * or several, the launch dialog opens on the new configuration to pick the cfg.
 */
public final class RobotSessionShortcut implements ILaunchShortcut {

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void launch(ISelection selection, String mode) {
        if (selection instanceof IStructuredSelection s && s.getFirstElement() instanceof IAdaptable a) {
            @Nullable IFile f = a.getAdapter(IFile.class);
            if (f != null) {
                launch(f, mode);
            }
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void launch(IEditorPart editor, String mode) {
        @Nullable IFile f = editor.getEditorInput().getAdapter(IFile.class);
        if (f != null) {
            launch(f, mode);
        }
    }

    private static void launch(IFile file, String mode) {
        try {
            if ("py".equals(file.getFileExtension())) {
                ILaunchConfiguration c = configurationForProgram(file);
                if (c.getAttribute(LaunchAttributes.CFG, "").isEmpty()) {
                    DebugUITools.openLaunchConfigurationDialog(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(),
                            c, DebugUITools.getLaunchGroup(c, mode).getIdentifier(), Status.info(
                                    "Choose the Player cfg for the Robot Session of " + file.getName()));
                    return;
                }
                DebugUITools.launch(c, mode);
                return;
            }
            DebugUITools.launch(configurationFor(file), mode);
        } catch (CoreException e) {
            SessionParts.log(e.getStatus());
        }
    }

    /**
     * The Robot Session configuration that runs {@code program}, made and saved if there is none yet
     * (its cfg: the only {@code .cfg} beside the program, else the only one in the project, else none).
     */
    public static ILaunchConfiguration configurationForProgram(IFile program) throws CoreException {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationType type = lm.getLaunchConfigurationType(LaunchAttributes.TYPE);
        String path = program.getFullPath().toString();
        for (ILaunchConfiguration c : lm.getLaunchConfigurations(type)) {
            if (path.equals(c.getAttribute(LaunchAttributes.PROGRAM, ""))) {
                return c;
            }
        }
        List<IFile> cfgs = cfgFiles(program.getParent(), false);
        if (cfgs.size() != 1) {
            cfgs = cfgFiles(program.getProject(), true);
        }
        ILaunchConfigurationWorkingCopy wc = type.newInstance(null, lm.generateLaunchConfigurationName(
                program.getName().replaceFirst("\\.py$", "")));
        new RobotSessionTab().setDefaults(wc);
        wc.setAttribute(LaunchAttributes.PROGRAM, path);
        if (cfgs.size() == 1) {
            wc.setAttribute(LaunchAttributes.CFG, cfgs.get(0).getFullPath().toString());
        }
        wc.setMappedResources(new IResource[] {program});
        return wc.doSave();
    }

    private static List<IFile> cfgFiles(IContainer in, boolean deep) throws CoreException {
        List<IFile> out = new ArrayList<>();
        in.accept(r -> {
            if (r instanceof IFile f && "cfg".equals(f.getFileExtension())) {
                out.add(f);
            }
            return r.equals(in) || (deep && !r.isDerived() && !r.getName().startsWith("."));
        }, IResource.DEPTH_INFINITE, false);
        return out;
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
