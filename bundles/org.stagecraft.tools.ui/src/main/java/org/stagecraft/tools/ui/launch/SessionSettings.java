package org.stagecraft.tools.ui.launch;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.Status;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.ToolSpec;
import org.stagecraft.tools.session.PlayerLocator;
import org.stagecraft.tools.session.SessionConfig;
import org.stagecraft.tools.session.SpyOptions;
import org.stagecraft.tools.types.ToolDefinition;
import org.stagecraft.tools.ui.prefs.ToolPreferences;
import org.stagecraft.tools.ui.registry.ToolTypeExtensionRegistry;

/**
 * A launch configuration read and checked: the files it names resolved in the workspace, the user
 * tools turned into what to run by their types, and the resulting {@link SessionConfig}. Every
 * problem becomes a {@link CoreException} that names the attribute, file or tool.
 */
record SessionSettings(SessionConfig config, @Nullable IFile cfgFile, @Nullable IFile program, @Nullable IProject project, @Nullable IContainer logFolder) {

    static SessionSettings read(ILaunchConfiguration c) throws CoreException {
        String cfgText = c.getAttribute(LaunchAttributes.CFG, "").trim();
        if (cfgText.isEmpty()) {
            throw error("no Player cfg file is set (Robot Session tab)");
        }
        IFile cfgFile = null;
        Path cfg;
        IResource r = ResourcesPlugin.getWorkspace().getRoot().findMember(cfgText);
        if (r instanceof IFile f && f.getLocation() != null) {
            cfgFile = f;
            cfg = f.getLocation().toPath();
        } else {
            cfg = Path.of(cfgText);
            if (!cfg.isAbsolute() || !Files.isRegularFile(cfg)) {
                throw error("Player cfg file " + cfgText + " does not exist (neither in the workspace nor on disk)");
            }
        }
        IFile program = null;
        String programText = c.getAttribute(LaunchAttributes.PROGRAM, "").trim();
        if (!programText.isEmpty()) {
            IResource p = ResourcesPlugin.getWorkspace().getRoot().findMember(programText);
            if (!(p instanceof IFile f) || f.getLocation() == null) {
                throw error("robot program " + programText + " does not exist in the workspace");
            }
            program = f;
        }
        IProject project = cfgFile != null ? cfgFile.getProject() : program != null ? program.getProject() : null;

        // launch configuration, preference (its default "player" counts as unset), install prefix, PATH
        PlayerLocator.Located player = PlayerLocator.fromSystem().locate(c.getAttribute(LaunchAttributes.PLAYER, ""),
                ToolPreferences.get(ToolPreferences.PLAYER), c.getAttribute(LaunchAttributes.PLAYER_ENVIRONMENT, Map.of()));
        RestartPolicy restart;
        try {
            restart = RestartPolicy.parse(c.getAttribute(LaunchAttributes.PLAYER_RESTART, "never"));
        } catch (IllegalArgumentException e) {
            throw error("Player " + e.getMessage());
        }
        int port = c.getAttribute(LaunchAttributes.DEFAULT_PORT, SessionConfig.PLAYER_DEFAULT_PORT);
        int seconds = c.getAttribute(LaunchAttributes.READY_SECONDS, 30);

        IContainer logFolder = null;
        Path log = null;
        String folder = c.getAttribute(LaunchAttributes.LOG_FOLDER, LaunchAttributes.DEFAULT_LOG_FOLDER).trim();
        if (!folder.isEmpty()) {
            if (project == null) {
                throw error("the spy log goes into the project of the cfg or the program, and neither is in the workspace");
            }
            logFolder = folder.equals("/") || folder.equals(".") ? project : project.getFolder(folder);
            String stamp = LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss-SSS"));
            String base = cfg.getFileName().toString().replaceFirst("\\.cfg$", "");
            log = logFolder.getLocation().toPath().resolve(base + "-" + stamp + ".mcap");
        }

        List<ToolSpec> tools = tools(c.getAttribute(LaunchAttributes.TOOLS, (List<String>) null));
        SessionConfig config;
        try {
            config = SessionConfig.of(cfg).withPlayer(List.of(player.program()), player.environment()).withDefaultPort(port)
                    .withPlayerRestart(restart, Duration.ofSeconds(seconds)).withTools(tools).withLog(log)
                    .withSpyOptions(spyOptions(c));
        } catch (IllegalArgumentException e) {
            throw error(e.getMessage());
        }
        return new SessionSettings(config, cfgFile, program, project, logFolder);
    }

    /** Robot holds, the frozen world, the watchdog and the upstream grace, as the Robot Session tab set them (defaults: {@link SpyOptions#DEFAULT}). */
    static SpyOptions spyOptions(ILaunchConfiguration c) throws CoreException {
        int grace = c.getAttribute(LaunchAttributes.UPSTREAM_GRACE_SECONDS, (int) SpyOptions.DEFAULT.upstreamGrace().toSeconds());
        if (grace < 0) {
            throw error("the upstream grace period of " + grace + " s is negative (Robot Session tab)");
        }
        boolean hold = c.getAttribute(LaunchAttributes.HOLD_WHEN_SUSPENDED, SpyOptions.DEFAULT.holdWhenSuspended());
        Duration watchdog = null;
        if (c.getAttribute(LaunchAttributes.WATCHDOG, false)) {
            int ms = c.getAttribute(LaunchAttributes.WATCHDOG_MILLIS, LaunchAttributes.DEFAULT_WATCHDOG_MILLIS);
            if (ms <= 0) {
                throw error("the silence watchdog's timeout of " + ms + " ms is not positive (Robot Session tab)");
            }
            watchdog = Duration.ofMillis(ms);
        }
        boolean freeze = c.getAttribute(LaunchAttributes.FREEZE_WORLD, SpyOptions.DEFAULT.freezeWorld());
        return new SpyOptions(Duration.ofSeconds(grace), hold, watchdog, freeze);
    }

    /** The user tools to start: the named ones (in preference order), or every enabled one. */
    private static List<ToolSpec> tools(List<String> names) throws CoreException {
        List<ToolSpec> out = new ArrayList<>();
        List<ToolTypeExtensionRegistry.Contribution> types = ToolTypeExtensionRegistry.load();
        List<ToolDefinition> defined = ToolPreferences.tools();
        if (names != null) {
            for (String n : names) {
                if (defined.stream().noneMatch(d -> d.name().equals(n))) {
                    throw error("tool '" + n + "' is not defined (Preferences > Stagecraft Tools)");
                }
            }
        }
        for (ToolDefinition d : defined) {
            if (names != null ? !names.contains(d.name()) : !d.enabled()) {
                continue;
            }
            ToolTypeExtensionRegistry.Contribution type = types.stream().filter(t -> t.id().equals(d.type())).findFirst()
                    .orElseThrow(() -> error("tool '" + d.name() + "' has type " + d.type()
                            + ", which no installed plug-in contributes"));
            try {
                out.add(type.type().toSpec(d));
            } catch (RuntimeException e) {
                throw error(e.getMessage());
            }
        }
        return out;
    }

    static CoreException error(String message) {
        return new CoreException(Status.error(message));
    }
}
