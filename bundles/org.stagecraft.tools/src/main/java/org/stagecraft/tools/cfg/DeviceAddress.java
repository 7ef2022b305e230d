package org.stagecraft.tools.cfg;

import java.util.OptionalInt;

/**
 * A device address as written in a {@code provides} or {@code requires} list. Player reads the
 * colon-separated fields from the right: {@code [key:][host:][robot:]interface:index}, where robot
 * is the TCP port. So {@code "position2d:0"} has no port (the {@code -p} default applies),
 * {@code "6666:position2d:0"} and {@code "localhost:6666:position2d:0"} name one, and in
 * {@code "odometry:::position2d:0"} key is "odometry" and host and port are empty.
 *
 * @param key  the key (empty if none), e.g. "odometry" for a driver with several position2d devices
 * @param host the host (empty if none)
 * @param port the port, or -1 when the address leaves it to {@code -p}
 */
public record DeviceAddress(String key, String host, int port, String iface, int index) {

    public OptionalInt explicitPort() {
        return port < 0 ? OptionalInt.empty() : OptionalInt.of(port);
    }

    /** The port this address is served on when Player runs with {@code -p defaultPort}. */
    public int portOr(int defaultPort) {
        return port < 0 ? defaultPort : port;
    }

    /** Whether the address names this machine (no host, or a loopback name), i.e. the Player being started. */
    public boolean isLocal() {
        return host.isEmpty() || host.equals("localhost") || host.startsWith("127.") || host.equals("::1");
    }

    /** The same address with another port, written in the same form as the original. */
    public String withPort(int newPort) {
        StringBuilder s = new StringBuilder();
        if (!key.isEmpty()) {
            s.append(key).append(':').append(host).append(':');
        } else if (!host.isEmpty()) {
            s.append(host).append(':');
        }
        s.append(newPort).append(':').append(iface).append(':').append(index);
        return s.toString();
    }

    /**
     * Parses the text of a {@code provides}/{@code requires} entry.
     *
     * @throws IllegalArgumentException naming what is wrong with it
     */
    public static DeviceAddress parse(String text) {
        String[] f = text.split(":", -1);
        if (f.length < 2 || f.length > 5) {
            throw new IllegalArgumentException("'" + text + "' is not a device address [key:][host:][port:]interface:index");
        }
        int n = f.length;
        String indexText = f[n - 1].trim();
        String iface = f[n - 2].trim();
        String robot = n >= 3 ? f[n - 3].trim() : "";
        String host = n >= 4 ? f[n - 4].trim() : "";
        String key = n >= 5 ? f[n - 5].trim() : "";
        if (iface.isEmpty() || !iface.chars().allMatch(c -> Character.isLetterOrDigit(c) || c == '_')) {
            throw new IllegalArgumentException("'" + text + "' has no valid interface name before the index");
        }
        int index;
        try {
            index = Integer.parseInt(indexText);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "' has index '" + indexText + "', not a number");
        }
        if (index < 0) {
            throw new IllegalArgumentException("'" + text + "' has a negative index");
        }
        int port = -1;
        if (!robot.isEmpty()) {
            try {
                port = Integer.parseInt(robot);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + text + "' has port '" + robot + "', not a number");
            }
            if (port < 1 || port > 65535) {
                throw new IllegalArgumentException("'" + text + "' has port " + port + ", not 1..65535");
            }
        }
        return new DeviceAddress(key, host, port, iface, index);
    }
}
