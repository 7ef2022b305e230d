package org.stagecraft.demo.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.Status;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.jdt.annotation.Nullable;
import org.osgi.service.prefs.BackingStoreException;
import org.stagecraft.demo.PlayerChoice;
import org.stagecraft.tools.session.SessionConfig;
import org.stagecraft.tools.types.ToolDefinition;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.prefs.ToolPreferences;

/**
 * The demo's Robot Session as an ordinary launch configuration ("Pioneer demo", in Run > Run
 * Configurations), so the user can run it again, change it, or copy it for their own robot: the
 * demo cfg, the chosen Player, spy logs in the project, and a robot program that fits that Player.
 * The recorded Player gets the recorded robot program (a helper tool replaying the recording's client
 * side: open loop, so it only makes sense against the same recording). A real Player gets a real,
 * closed-loop program, Sunday Stroll, run as the session's robot program, so the robot strolls in the
 * cave for as long as the demo runs.
 */
final class DemoLaunch {
    static final String NAME = "Pioneer demo";

    private DemoLaunch() {
    }

    static final String STROLL = "programs/sunday_stroll.py";

    static ILaunchConfiguration configure(IProject project, PlayerChoice player, Path recording, @Nullable String python)
            throws CoreException {
        try {
            List<ToolDefinition> tools = new ArrayList<>(ToolPreferences.tools());
            tools.removeIf(t -> t.name().equals(RecordedPrograms.ROBOT_TOOL));
            if (player.recorded()) {
                tools.add(RecordedPrograms.robotTool(recording, SessionConfig.PLAYER_DEFAULT_PORT));
            } else if (python != null) {
                // the interpreter ./stagecraft demo prepared (with pint); the client comes from the bundle
                ToolPreferences.set(ToolPreferences.PYTHON, python);
            }
            ToolPreferences.setTools(tools);
        } catch (IOException | BackingStoreException e) {
            throw new CoreException(Status.error("cannot set up the demo's robot program: " + e.getMessage(), e));
        }
        if (!player.recorded() && !project.getFile(STROLL).exists()) {
            throw new CoreException(Status.error("the demo project has no " + STROLL + " to drive the robot with"));
        }
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationType type = lm.getLaunchConfigurationType(LaunchAttributes.TYPE);
        ILaunchConfigurationWorkingCopy wc = null;
        for (ILaunchConfiguration c : lm.getLaunchConfigurations(type)) {
            if (c.getName().equals(NAME)) {
                wc = c.getWorkingCopy();
            }
        }
        if (wc == null) {
            wc = type.newInstance(null, NAME);
        }
        wc.setAttribute(LaunchAttributes.CFG, project.getFile(DemoProject.CFG).getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PROGRAM, player.recorded() ? "" : project.getFile(STROLL).getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PLAYER, player.program());
        wc.setAttribute(LaunchAttributes.PLAYER_ENVIRONMENT,
                player.recorded() ? Map.of(RecordedPrograms.RECORDING_VARIABLE, recording.toString()) : Map.of());
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, SessionConfig.PLAYER_DEFAULT_PORT);
        wc.setAttribute(LaunchAttributes.PLAYER_RESTART, "never");
        wc.setAttribute(LaunchAttributes.READY_SECONDS, 30);
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, DemoProject.LOG_FOLDER);
        wc.setAttribute(LaunchAttributes.TOOLS, player.recorded() ? List.of(RecordedPrograms.ROBOT_TOOL) : List.of());
        return wc.doSave();
    }

    static ILaunch launch(ILaunchConfiguration config, IProgressMonitor monitor) throws CoreException {
        return config.launch(ILaunchManager.RUN_MODE, monitor);
    }
}
