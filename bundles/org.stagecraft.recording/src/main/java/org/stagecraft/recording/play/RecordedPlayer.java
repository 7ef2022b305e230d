package org.stagecraft.recording.play;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import java.util.function.Supplier;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Stands in for Player with a recording: listens on Player's ports and serves every accepted
 * connection the server side of a recorded connection (the banner, the replies and the data, each
 * chunk at its recorded moment), whatever the client says. What the client sends is compared with
 * what the recorded client sent, so a relay in between can be checked byte for byte.
 *
 * <p>Which recorded connection a client gets: the n-th connection accepted (over all ports) gets the
 * recording's connection n modulo their number. A rewritten cfg moves Player's ports, so the
 * recorded port numbers cannot be used to choose.
 */
public final class RecordedPlayer implements AutoCloseable {
    /** One served connection, reported when it ended. */
    public record Served(int port, int recordedConn, @Nullable ExchangeResult result, @Nullable String error) {
        public String describe() {
            return "served recorded connection " + recordedConn + " on port " + port + ": "
                    + (error != null ? "ended early: " + error : result.describe("robot program"));
        }
    }

    private final @Nullable TimedRecording recording;
    private final double speed;
    private final Consumer<Served> report;
    private final List<ServerSocket> servers = new ArrayList<>();
    private final Set<Socket> open = ConcurrentHashMap.newKeySet();
    private final AtomicInteger accepted = new AtomicInteger();
    private final ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();

    public RecordedPlayer(@Nullable TimedRecording recording, double speed, Consumer<Served> report) {
        this.recording = recording;
        this.speed = speed;
        this.report = report;
    }

    /** For {@link #start(Collection)} only: each listener brings its own recorded connections. */
    public RecordedPlayer(double speed, Consumer<Served> report) {
        this(null, speed, report);
    }

    /**
     * One address to listen on and the recorded connections it serves: the n-th client it accepts
     * gets connection n modulo their number.
     */
    public record Listener(InetSocketAddress address, List<? extends PlayableConnection> connections) {
        public Listener {
            connections = List.copyOf(connections);
            if (connections.isEmpty()) {
                throw new IllegalArgumentException("a listener on " + address + " needs a recorded connection to serve");
            }
        }
    }

    /** Binds every port on the loopback interface (all or none) and starts accepting. */
    public synchronized void start(List<Integer> ports) throws IOException {
        if (recording == null) {
            throw new IllegalStateException("no recording to serve on bare ports: start with listeners");
        }
        List<InetSocketAddress> addresses = ports.stream()
                .map(p -> new InetSocketAddress(InetAddress.getLoopbackAddress(), p)).toList();
        bind(addresses);
        for (ServerSocket s : servers) {
            threads.submit(() -> acceptLoop(s, () -> recording.connections()
                    .get(accepted.getAndIncrement() % recording.connections().size())));
        }
    }

    /**
     * Binds every listener's address (all or none) and starts accepting; each listener serves its
     * own recorded connections, so a recorded port's traffic is served on the address chosen for it.
     */
    public synchronized void start(Collection<Listener> listeners) throws IOException {
        List<Listener> list = List.copyOf(listeners);
        int first = servers.size();
        bind(list.stream().map(Listener::address).toList());
        for (int i = 0; i < list.size(); i++) {
            Listener l = list.get(i);
            ServerSocket server = servers.get(first + i);
            AtomicInteger n = new AtomicInteger();
            threads.submit(() -> acceptLoop(server, () -> l.connections().get(n.getAndIncrement() % l.connections().size())));
        }
    }

    private void bind(List<InetSocketAddress> addresses) throws IOException {
        int first = servers.size();
        try {
            for (InetSocketAddress a : addresses) {
                ServerSocket s = new ServerSocket();
                servers.add(s);
                s.bind(a, 50);
            }
        } catch (IOException e) {
            close();
            InetSocketAddress a = addresses.get(servers.size() - 1 - first);
            throw new IOException("cannot listen on " + (a.getAddress().isLoopbackAddress() ? "port " + a.getPort()
                    : a.getHostString() + ":" + a.getPort()) + ": " + e.getMessage(), e);
        }
    }

    /** The ports it listens on (useful with port 0). */
    public synchronized List<Integer> ports() {
        return servers.stream().map(ServerSocket::getLocalPort).toList();
    }

    private @Nullable Void acceptLoop(ServerSocket server, Supplier<? extends PlayableConnection> next) {
        while (!server.isClosed()) {
            Socket client;
            try {
                client = server.accept();
            } catch (IOException e) {
                return null; // closed
            }
            open.add(client);
            PlayableConnection conn = next.get();
            threads.submit(() -> serve(client, server.getLocalPort(), conn));
        }
        return null;
    }

    private @Nullable Void serve(Socket client, int port, PlayableConnection conn) {
        try (client; ChunkSource send = conn.openServer(); ChunkSource expected = conn.openClient()) {
            ExchangeResult r = Exchange.play(client, send, expected, conn.length(), speed);
            report.accept(new Served(port, conn.conn(), r, null));
        } catch (IOException e) {
            report.accept(new Served(port, conn.conn(), null, e.getMessage()));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            open.remove(client);
        }
        return null;
    }

    @Override
    public synchronized void close() {
        for (ServerSocket s : servers) {
            try {
                s.close();
            } catch (IOException e) {
                // closing a listening socket only fails if it is already gone
            }
        }
        for (Socket s : open) {
            try {
                s.close();
            } catch (IOException e) {
                // the connection is being dropped anyway
            }
        }
        threads.shutdownNow();
    }
}
