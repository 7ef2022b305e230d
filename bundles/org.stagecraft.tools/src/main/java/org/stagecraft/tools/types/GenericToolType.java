package org.stagecraft.tools.types;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.ToolSpec;

/** Any program: the command and arguments as written, with the readiness and restart policy given. */
public final class GenericToolType implements ToolType {
    public static final String ID = "org.stagecraft.tools.generic";

    @Override
    public ToolSpec toSpec(ToolDefinition d) {
        if (d.command().isBlank()) {
            throw new IllegalArgumentException("tool '" + d.name() + "': no command given");
        }
        List<String> command = new ArrayList<>();
        command.add(d.command().trim());
        try {
            command.addAll(CommandLine.split(d.arguments()));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("tool '" + d.name() + "': arguments: " + e.getMessage(), e);
        }
        Readiness readiness = readiness(d);
        RestartPolicy restart;
        try {
            restart = RestartPolicy.parse(d.restart());
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("tool '" + d.name() + "': " + e.getMessage(), e);
        }
        return new ToolSpec(d.name(), command, d.workingDir().isBlank() ? null : Path.of(d.workingDir()), d.environment(),
                readiness, restart, Duration.ofSeconds(d.readyWithinSeconds()));
    }

    /** Parses the readiness text of a definition. */
    public static Readiness readiness(ToolDefinition d) {
        String r = d.readiness().trim();
        if (r.isEmpty() || r.equals("started")) {
            return Readiness.started();
        }
        try {
            if (r.startsWith("line:")) {
                return Readiness.line(r.substring(5));
            }
            if (r.startsWith("port:")) {
                String rest = r.substring(5);
                String host = "127.0.0.1";
                int colon = rest.lastIndexOf(':');
                if (colon >= 0) {
                    host = rest.substring(0, colon);
                    rest = rest.substring(colon + 1);
                }
                List<Integer> ports = Arrays.stream(rest.split(",")).map(String::trim).map(Integer::parseInt).toList();
                return Readiness.ports(host, ports);
            }
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("tool '" + d.name() + "': readiness '" + r + "': " + e.getMessage(), e);
        }
        throw new IllegalArgumentException("tool '" + d.name() + "': readiness '" + r
                + "' is not empty, port:PORT[,PORT], port:HOST:PORT or line:REGEX");
    }
}
