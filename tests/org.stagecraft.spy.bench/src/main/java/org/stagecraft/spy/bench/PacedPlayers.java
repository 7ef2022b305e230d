package org.stagecraft.spy.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.stagecraft.player.wire.Direction;

/**
 * The Player side at the recorded pace: one port per timed session, playing the server's chunks at
 * their recorded times to each client (and checking what the client sent), plus the ping port.
 */
final class PacedPlayers implements AutoCloseable {
    private final List<ServerSocket> sockets = new ArrayList<>();
    private final BlockingQueue<Object> served = new LinkedBlockingQueue<>();

    PacedPlayers(List<TimedSession> sessions, Workload w) throws IOException {
        for (TimedSession session : sessions) {
            ServerSocket s = listen();
            Thread.ofVirtual().start(() -> RecordedPlayers.acceptLoop(s, socket -> {
                try {
                    served.add(session.play(socket, Direction.SERVER_TO_CLIENT));
                } catch (IOException | RuntimeException e) {
                    served.add(e);
                }
            }));
        }
        ServerSocket ping = listen();
        Thread.ofVirtual().start(() -> RecordedPlayers.acceptLoop(ping, socket -> RecordedPlayers.answerPings(socket, w)));
    }

    /** The sessions' ports in order, then the ping port. */
    List<InetSocketAddress> addresses() {
        return sockets.stream().map(s -> (InetSocketAddress) s.getLocalSocketAddress()).toList();
    }

    void verifyServed(int n) throws Exception {
        for (int i = 0; i < n; i++) {
            Object r = served.poll(120, TimeUnit.SECONDS);
            if (!Boolean.TRUE.equals(r)) {
                throw new IllegalStateException("a paced Player side saw other bytes than recorded, or failed: " + r);
            }
        }
    }

    private ServerSocket listen() throws IOException {
        ServerSocket s = new ServerSocket(0, 500, InetAddress.getLoopbackAddress());
        sockets.add(s);
        return s;
    }

    @Override
    public void close() throws IOException {
        for (ServerSocket s : sockets) {
            s.close();
        }
    }
}
