package org.stagecraft.tools.process;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;

/**
 * How to run one external tool.
 *
 * @param command     the program and its arguments; the program is looked up on PATH unless it is a path
 * @param workingDir  where it runs, or null for the current directory
 * @param environment added to (and overriding) the inherited environment
 * @param readyWithin how long the readiness check may take at each start
 */
public record ToolSpec(String name, List<String> command, @Nullable Path workingDir, Map<String, String> environment,
        Readiness readiness, RestartPolicy restart, Duration readyWithin) {

    public static final Duration DEFAULT_READY_WITHIN = Duration.ofSeconds(30);

    public ToolSpec {
        Objects.requireNonNull(name, "name");
        command = List.copyOf(command);
        if (command.isEmpty() || command.get(0).isBlank()) {
            throw new IllegalArgumentException("tool '" + name + "' has no command");
        }
        environment = Map.copyOf(environment);
        Objects.requireNonNull(readiness, "readiness");
        Objects.requireNonNull(restart, "restart");
        Objects.requireNonNull(readyWithin, "readyWithin");
    }

    public static ToolSpec of(String name, List<String> command) {
        return new ToolSpec(name, command, null, Map.of(), Readiness.started(), RestartPolicy.NEVER, DEFAULT_READY_WITHIN);
    }

    public ToolSpec withWorkingDir(Path dir) {
        return new ToolSpec(name, command, dir, environment, readiness, restart, readyWithin);
    }

    public ToolSpec withEnvironment(Map<String, String> env) {
        return new ToolSpec(name, command, workingDir, env, readiness, restart, readyWithin);
    }

    public ToolSpec withReadiness(Readiness r, Duration within) {
        return new ToolSpec(name, command, workingDir, environment, r, restart, within);
    }

    public ToolSpec withRestart(RestartPolicy policy) {
        return new ToolSpec(name, command, workingDir, environment, readiness, policy, readyWithin);
    }
}
