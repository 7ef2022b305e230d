package org.stagecraft.tools.session;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;

/** Free-port questions, asked the only reliable way: by binding. */
public final class Ports {
    private Ports() {
    }

    /**
     * {@code n} distinct ports that were free on {@code host} a moment ago. All are held open
     * together while they are chosen so the system cannot hand out one twice; another program may
     * still take one before Player binds it, which Player's readiness check then reports.
     */
    public static List<Integer> free(String host, int n) throws IOException {
        List<ServerSocket> held = new ArrayList<>();
        try {
            InetAddress addr = InetAddress.getByName(host);
            List<Integer> ports = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                ServerSocket s = new ServerSocket();
                held.add(s);
                s.setReuseAddress(false);
                s.bind(new InetSocketAddress(addr, 0));
                ports.add(s.getLocalPort());
            }
            return ports;
        } finally {
            for (ServerSocket s : held) {
                s.close();
            }
        }
    }

    /** Whether {@code port} can be bound on {@code host} now. */
    public static boolean isFree(@Nullable String host, int port) {
        try (ServerSocket s = new ServerSocket()) {
            s.setReuseAddress(true);
            s.bind(new InetSocketAddress(InetAddress.getByName(host), port));
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
