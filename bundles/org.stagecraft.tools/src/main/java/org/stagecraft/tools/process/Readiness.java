package org.stagecraft.tools.process;

import java.util.List;
import java.util.regex.Pattern;

/** When a started tool counts as ready for the next part of a session to rely on it. */
public sealed interface Readiness {

    /** Ready as soon as the process runs. */
    record Started() implements Readiness {
    }

    /** Ready when every port accepts a TCP connection on {@code host}. */
    record PortsOpen(String host, List<Integer> ports) implements Readiness {
        public PortsOpen {
            ports = List.copyOf(ports);
            if (ports.isEmpty()) {
                throw new IllegalArgumentException("a port readiness check needs at least one port");
            }
        }
    }

    /** Ready when a line of standard output or standard error matches {@code pattern} (find, not match). */
    record OutputLine(Pattern pattern) implements Readiness {
    }

    static Readiness started() {
        return new Started();
    }

    static Readiness ports(String host, List<Integer> ports) {
        return new PortsOpen(host, ports);
    }

    static Readiness line(String regex) {
        return new OutputLine(Pattern.compile(regex));
    }

    /** For messages: "port 127.0.0.1:6665 open", "a line matching 'ready'". */
    default String describe() {
        return switch (this) {
            case Started s -> "the process started";
            case PortsOpen p -> (p.ports().size() == 1 ? "port " : "ports ") + p.host() + ":"
                    + String.join(",", p.ports().stream().map(String::valueOf).toList()) + " open";
            case OutputLine l -> "a line matching '" + l.pattern().pattern() + "'";
        };
    }
}
