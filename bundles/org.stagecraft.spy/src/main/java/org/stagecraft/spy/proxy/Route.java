package org.stagecraft.spy.proxy;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;

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
    }

    /** Listens on the loopback address at {@code listenPort}. */
    public static Route loopback(int listenPort, String upstreamHost, int upstreamPort) {
        return of(DEFAULT_BIND, listenPort, upstreamHost, upstreamPort);
    }

    public static Route of(String bindHost, int listenPort, String upstreamHost, int upstreamPort) {
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
