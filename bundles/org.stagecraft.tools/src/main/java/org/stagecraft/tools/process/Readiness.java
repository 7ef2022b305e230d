package org.stagecraft.tools.process;

import java.util.List;
import java.util.regex.Pattern;

/** When a started tool counts as ready for the next part of a session to rely on it. */
public sealed interface Readiness {

    /** Ready as soon as the process runs. */
    record Started() implements Readiness {
    }

    /**
     * Ready when every port on {@code host} accepts a TCP connection and, if {@code bannerBytes} is
     * positive, sends that many bytes of greeting first (Player's 32-byte ident string), checked by
     * {@link PortProbe} the way a client would connect.
     */
    record PortsOpen(String host, List<Integer> ports, int bannerBytes) implements Readiness {
        public PortsOpen {
            ports = List.copyOf(ports);
            if (ports.isEmpty()) {
                throw new IllegalArgumentException("a port readiness check needs at least one port");
            }
            if (bannerBytes < 0) {
                throw new IllegalArgumentException("banner length " + bannerBytes + " < 0");
            }
        }

        /** Ports that need only accept a connection (a tool that greets no one). */
        public PortsOpen(String host, List<Integer> ports) {
            this(host, ports, 0);
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

    /**
     * Player's ports: each accepts a connection and sends its ident string (banner), which the
     * check reads before it closes, so Player sees an ordinary client come and go.
     */
    static Readiness playerPorts(String host, List<Integer> ports) {
        return new PortsOpen(host, ports, PortProbe.PLAYER_BANNER_BYTES);
    }

    static Readiness line(String regex) {
        return new OutputLine(Pattern.compile(regex));
    }

    /** For messages: "port 127.0.0.1:6665 open", "a line matching 'ready'". */
    default String describe() {
        return switch (this) {
            case Started s -> "the process started";
            case PortsOpen p -> (p.ports().size() == 1 ? "port " : "ports ") + p.host() + ":"
                    + String.join(",", p.ports().stream().map(String::valueOf).toList()) + " open"
                    + (p.bannerBytes() > 0 ? " (with a " + p.bannerBytes() + "-byte banner)" : "");
            case OutputLine l -> "a line matching '" + l.pattern().pattern() + "'";
        };
    }
}
