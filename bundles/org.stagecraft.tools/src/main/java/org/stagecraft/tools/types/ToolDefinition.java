package org.stagecraft.tools.types;

import java.util.Map;
import java.util.Objects;

/**
 * A tool as the user defines it (in the preferences): plain text fields, checked and turned into a
 * {@link org.stagecraft.tools.process.ToolSpec} by the tool's {@link ToolType}.
 *
 * @param type       id of the tool type (see {@link GenericToolType#ID})
 * @param arguments  one string, split like a shell does (quotes group words)
 * @param readiness  "" (started), "port:PORT[,PORT...]" or "port:HOST:PORT", or "line:REGEX"
 * @param restart    "never", "on-failure[:N]" or "always[:N]"
 * @param readyWithinSeconds how long its readiness check may take
 */
public record ToolDefinition(String name, String type, String command, String arguments, String workingDir,
        Map<String, String> environment, String readiness, String restart, int readyWithinSeconds, boolean enabled) {

    public ToolDefinition {
        Objects.requireNonNull(name, "name");
        type = type == null || type.isBlank() ? GenericToolType.ID : type;
        command = command == null ? "" : command;
        arguments = arguments == null ? "" : arguments;
        workingDir = workingDir == null ? "" : workingDir;
        environment = environment == null ? Map.of() : Map.copyOf(environment);
        readiness = readiness == null ? "" : readiness;
        restart = restart == null ? "never" : restart;
        readyWithinSeconds = readyWithinSeconds <= 0 ? 30 : readyWithinSeconds;
    }

    public static ToolDefinition of(String name, String command, String arguments) {
        return new ToolDefinition(name, GenericToolType.ID, command, arguments, "", Map.of(), "", "never", 30, true);
    }
}
