package org.stagecraft.spy.proxy;

import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.util.Locale;

/**
 * Says why a listen address could not be bound, in the user's terms. Java reports EADDRINUSE,
 * EADDRNOTAVAIL and EACCES all as a {@link BindException}; only the system's message tells them
 * apart, so it is read here (and, for an address that is not this machine's, confirmed against the
 * network interfaces).
 */
final class BindFailure {
    private BindFailure() {
    }

    static String explain(InetSocketAddress address, Exception e) {
        String ip = address.getAddress().getHostAddress();
        String message = e.getMessage() == null ? "" : e.getMessage().toLowerCase(Locale.ROOT);
        if (message.contains("already in use")) {
            return "port " + address.getPort() + " is already in use on " + ip;
        }
        if (message.contains("assign requested address") || !isLocal(address.getAddress())) {
            return ip + " is not an address of this machine: use 127.0.0.1, 0.0.0.0 or one of its own addresses";
        }
        if (message.contains("permission denied") || message.contains("access")) {
            return "permission denied" + (address.getPort() < 1024 ? ": ports below 1024 need administrator rights" : "");
        }
        return e.getMessage();
    }

    private static boolean isLocal(InetAddress a) {
        if (a.isAnyLocalAddress() || a.isLoopbackAddress()) {
            return true;
        }
        try {
            return NetworkInterface.getByInetAddress(a) != null;
        } catch (SocketException e) {
            return true; // cannot tell: do not claim it is foreign
        }
    }
}
