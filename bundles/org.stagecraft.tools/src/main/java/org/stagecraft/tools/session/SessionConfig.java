package org.stagecraft.tools.session;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.ToolSpec;

/**
 * Everything a robot session needs to start.
 *
 * @param cfg           the user's Player configuration file (never modified)
 * @param playerCommand the Player program (and any leading arguments); the session appends
 *                      {@code -p PORT RewrittenCfg} exactly as one runs Player by hand
 * @param defaultPort   what the user would give as {@code player -p} (6665 when not given)
 * @param tools         started in order before Player, each waited for until it is ready
 * @param log           the spy log to write, or null for none
 * @param bindHost      where the spy listens for robot programs (loopback unless the user says otherwise)
 * @param scratchRoot   where session scratch directories go, or null for the default
 * @param spy           robot holds, the silence watchdog and the upstream grace of the spy (null: {@link SpyOptions#DEFAULT})
 */
public record SessionConfig(Path cfg, List<String> playerCommand, int defaultPort, Map<String, String> playerEnvironment,
        RestartPolicy playerRestart, Duration playerReadyWithin, List<ToolSpec> tools, @Nullable Path log, @Nullable String bindHost,
        @Nullable Path scratchRoot, SpyOptions spy) {

    public static final int PLAYER_DEFAULT_PORT = 6665;

    public SessionConfig {
        Objects.requireNonNull(cfg, "cfg");
        playerCommand = List.copyOf(playerCommand);
        if (playerCommand.isEmpty() || playerCommand.get(0).isBlank()) {
            throw new IllegalArgumentException("no Player program given");
        }
        if (defaultPort < 1 || defaultPort > 65535) {
            throw new IllegalArgumentException("Player's default port " + defaultPort + " is not 1..65535");
        }
        playerEnvironment = Map.copyOf(playerEnvironment);
        tools = List.copyOf(tools);
        Objects.requireNonNull(playerRestart, "playerRestart");
        Objects.requireNonNull(playerReadyWithin, "playerReadyWithin");
        bindHost = bindHost == null || bindHost.isBlank() ? "127.0.0.1" : bindHost;
        spy = spy == null ? SpyOptions.DEFAULT : spy;
    }

    /** A session with Player from PATH, default port, no user tools, no log. */
    public static SessionConfig of(Path cfg) {
        return new SessionConfig(cfg, List.of("player"), PLAYER_DEFAULT_PORT, Map.of(), RestartPolicy.NEVER,
                ToolSpec.DEFAULT_READY_WITHIN, List.of(), null, null, null, SpyOptions.DEFAULT);
    }

    public SessionConfig withPlayer(List<String> command, Map<String, String> env) {
        return new SessionConfig(cfg, command, defaultPort, env, playerRestart, playerReadyWithin, tools, log, bindHost,
                scratchRoot, spy);
    }

    public SessionConfig withDefaultPort(int port) {
        return new SessionConfig(cfg, playerCommand, port, playerEnvironment, playerRestart, playerReadyWithin, tools, log,
                bindHost, scratchRoot, spy);
    }

    public SessionConfig withPlayerRestart(RestartPolicy policy, Duration readyWithin) {
        return new SessionConfig(cfg, playerCommand, defaultPort, playerEnvironment, policy, readyWithin, tools, log,
                bindHost, scratchRoot, spy);
    }

    public SessionConfig withTools(List<ToolSpec> t) {
        return new SessionConfig(cfg, playerCommand, defaultPort, playerEnvironment, playerRestart, playerReadyWithin, t, log,
                bindHost, scratchRoot, spy);
    }

    public SessionConfig withLog(@Nullable Path file) {
        return new SessionConfig(cfg, playerCommand, defaultPort, playerEnvironment, playerRestart, playerReadyWithin, tools,
                file, bindHost, scratchRoot, spy);
    }

    public SessionConfig withScratchRoot(Path root) {
        return new SessionConfig(cfg, playerCommand, defaultPort, playerEnvironment, playerRestart, playerReadyWithin, tools,
                log, bindHost, root, spy);
    }

    public SessionConfig withSpyOptions(SpyOptions options) {
        return new SessionConfig(cfg, playerCommand, defaultPort, playerEnvironment, playerRestart, playerReadyWithin, tools,
                log, bindHost, scratchRoot, options);
    }
}
