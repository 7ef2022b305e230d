package org.stagecraft.spy.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;

import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;

/**
 * The Player side of the benchmark: one port per recorded session, serving that session's server
 * stream to every client (and checking what each client sent), plus one port that answers the
 * ping probe's request with a recorded reply, after the banner as Player would.
 */
final class RecordedPlayers implements AutoCloseable {
    private final List<ServerSocket> sockets = new ArrayList<>();
    private final BlockingQueue<Object> served = new LinkedBlockingQueue<>();

    RecordedPlayers(Workload w) throws IOException {
        List<RecordedConnection> all = new ArrayList<>(w.sessions());
        all.addAll(w.warmUp());
        for (RecordedConnection session : all) {
            ServerSocket s = listen();
            Thread.ofVirtual().start(() -> acceptLoop(s, socket -> {
                try {
                    served.add(ReplayPeer.serve(socket, session));
                } catch (IOException e) {
                    served.add(e);
                }
            }));
        }
        ServerSocket ping = listen();
        Thread.ofVirtual().start(() -> acceptLoop(ping, socket -> answerPings(socket, w)));
    }

    /** The load's session ports first, then the warm-up sessions' ports, in workload order; the ping port last. */
    List<InetSocketAddress> addresses() {
        return sockets.stream().map(s -> (InetSocketAddress) s.getLocalSocketAddress()).toList();
    }

    /** Waits for the server side of {@code n} sessions and fails if any saw other bytes than recorded. */
    void verifyServed(int n) throws Exception {
        for (int i = 0; i < n; i++) {
            Object r = served.poll(120, java.util.concurrent.TimeUnit.SECONDS);
            if (r instanceof ReplayPeer.Result res) {
                if (!res.matches()) {
                    throw new IllegalStateException("Player received other bytes than recorded, from byte " + res.firstDifference());
                }
            } else {
                throw new IllegalStateException("a Player side failed: " + r);
            }
        }
    }

    private ServerSocket listen() throws IOException {
        ServerSocket s = new ServerSocket(0, 500, InetAddress.getLoopbackAddress());
        sockets.add(s);
        return s;
    }

    interface Handler {
        void handle(Socket s);
    }

    static void acceptLoop(ServerSocket server, Handler handler) {
        while (!server.isClosed()) {
            try {
                Socket s = server.accept();
                Thread.ofVirtual().start(() -> handler.handle(s));
            } catch (IOException closed) {
                return;
            }
        }
    }

    static void answerPings(Socket s, Workload w) {
        try (s) {
            s.setTcpNoDelay(true);
            InputStream in = s.getInputStream();
            OutputStream out = s.getOutputStream();
            out.write(w.banner());
            byte[] request = new byte[w.pingRequest().length];
            while (in.readNBytes(request, 0, request.length) == request.length) {
                out.write(w.pingReply());
            }
        } catch (IOException e) {
            // the probe (or a relay's readiness check) hung up
        }
    }

    @Override
    public void close() throws IOException {
        for (ServerSocket s : sockets) {
            s.close();
        }
    }
}
