package org.stagecraft.spy.proxy;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.net.UnknownHostException;

import org.eclipse.jdt.annotation.Nullable;

/**
 * One spied port: robot programs connect to {@code listen}; each connection is relayed to
 * {@code upstream}, where Player really listens.
 */
public record Route(InetSocketAddress listen, InetSocketAddress upstream) {

    /** Loopback: a spy is reachable from other machines only when the user asks for it. */
    public static final String DEFAULT_BIND = "127.0.0.1";

    public Route {
        if (listen.getPort() < 0 || listen.getPort() > 65535) {
            throw new IllegalArgumentException("listen port " + listen.getPort() + " is not 0..65535");
        }
        if (upstream.getPort() < 1 || upstream.getPort() > 65535) {
            throw new IllegalArgumentException("upstream port " + upstream.getPort() + " is not 1..65535");
        }
        if (leadsBackToItself(listen, upstream)) {
            throw new IllegalArgumentException("the route " + text(listen) + " -> " + text(upstream)
                    + " leads back to the spy itself (it would relay its own connections to itself without end);"
                    + " --to must name where Player really listens: another port, or another machine");
        }
    }

    /**
     * Whether connecting to {@code upstream} would reach the spy's own listening socket: same port,
     * and the upstream address is the listen address, or the listen address is the wildcard
     * (0.0.0.0) and the upstream is any address of this machine, or the upstream is the wildcard
     * (which a connect treats as this machine).
     */
    static boolean leadsBackToItself(InetSocketAddress listen, InetSocketAddress upstream) {
        InetAddress l = listen.getAddress();
        InetAddress u = upstream.getAddress();
        if (l == null || u == null || listen.getPort() == 0 || listen.getPort() != upstream.getPort()) {
            return false;
        }
        if (l.equals(u)) {
            return true;
        }
        if (u.isAnyLocalAddress()) {
            return isThisMachine(l);
        }
        return l.isAnyLocalAddress() && isThisMachine(u);
    }

    private static boolean isThisMachine(InetAddress a) {
        if (a.isAnyLocalAddress() || a.isLoopbackAddress()) {
            return true;
        }
        try {
            return NetworkInterface.getByInetAddress(a) != null;
        } catch (SocketException e) {
            return false;
        }
    }

    /** Listens on the loopback address at {@code listenPort}. */
    public static Route loopback(int listenPort, String upstreamHost, int upstreamPort) {
        return of(DEFAULT_BIND, listenPort, upstreamHost, upstreamPort);
    }

    public static Route of(@Nullable String bindHost, int listenPort, String upstreamHost, int upstreamPort) {
        try {
            return new Route(new InetSocketAddress(InetAddress.getByName(bindHost), listenPort),
                    new InetSocketAddress(InetAddress.getByName(upstreamHost), upstreamPort));
        } catch (UnknownHostException e) {
            throw new IllegalArgumentException("unknown host: " + e.getMessage(), e);
        }
    }

    /** Parses "HOST:PORT" or "PORT" (host defaulting to {@code defaultHost}). */
    public static InetSocketAddress address(String text, String defaultHost) {
        String host = defaultHost;
        String port = text;
        int colon = text.lastIndexOf(':');
        if (colon >= 0) {
            host = text.substring(0, colon);
            port = text.substring(colon + 1);
        }
        int p;
        try {
            p = Integer.parseInt(port);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "' is not HOST:PORT or PORT", e);
        }
        if (p < 0 || p > 65535) {
            throw new IllegalArgumentException("port " + p + " in '" + text + "' is not 0..65535");
        }
        try {
            return new InetSocketAddress(InetAddress.getByName(host), p);
        } catch (UnknownHostException e) {
            throw new IllegalArgumentException("unknown host '" + host + "' in '" + text + "'", e);
        }
    }

    @Override
    public String toString() {
        return text(listen) + " -> " + text(upstream);
    }

    static String text(InetSocketAddress a) {
        return a.getAddress().getHostAddress() + ":" + a.getPort();
    }
}
