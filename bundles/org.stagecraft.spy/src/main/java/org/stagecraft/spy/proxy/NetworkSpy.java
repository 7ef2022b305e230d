package org.stagecraft.spy.proxy;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldObserver;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.HoldingForwarder;
import org.stagecraft.spy.hold.RobotHold;

/**
 * The Network Spy's relay: a transparent TCP proxy between robot programs and Player. For each
 * {@link Route} it accepts any number of connections and opens one upstream connection per client.
 * Bytes are forwarded unchanged and in order, and only then handed to the {@link WireObserver};
 * nothing the observer does can delay or alter them. Half-close, resets and upstream refusal are
 * passed on the way a direct connection would show them. Both sockets use TCP_NODELAY: Player's
 * request/reply rounds are many small writes, which Nagle's algorithm would hold back.
 */
public final class NetworkSpy implements AutoCloseable {
    private static final int BUFFER = 64 * 1024;
    private static final int CONNECT_TIMEOUT_MS = 5_000;
    /**
     * One platform thread per direction, blocking in read(): the kernel wakes exactly the thread
     * whose socket has data, so a robot program's small request is not queued behind bulk
     * transfers on other connections (virtual threads share a few carriers first come, first served,
     * which the relay benchmark showed as milliseconds of added latency under load). Two threads per
     * connection stay cheap at the sixty-robot scale. (A Thread.Builder is not thread-safe, hence a
     * new one per thread.)
     */
    private static Thread startThread(String name, Runnable body) {
        return Thread.ofPlatform().daemon().name(name).start(body);
    }

    private final List<Route> routes;
    private final WireObserver observer;
    private final List<ServerSocket> servers = new ArrayList<>();
    private final Set<Relay> relays = ConcurrentHashMap.newKeySet();
    private final AtomicInteger nextId = new AtomicInteger(1);
    private final LongAdder bytesC2S = new LongAdder();
    private final LongAdder bytesS2C = new LongAdder();
    private final LongAdder connectionsTotal = new LongAdder();
    private final LongAdder observerFailures = new LongAdder();
    private volatile boolean closed;
    private final RobotHold holds;

    public NetworkSpy(List<Route> routes, WireObserver observer) {
        if (routes.isEmpty()) {
            throw new IllegalArgumentException("a spy needs at least one --listen/--to route");
        }
        this.routes = List.copyOf(routes);
        this.observer = observer;
        this.holds = new RobotHold(new HoldObserver() {
            @Override
            public void action(HoldAction a) {
                observe(() -> observer.holdAction(a, WallClock.nowNanos()));
            }

            @Override
            public void state(HoldState s) {
                observe(() -> observer.holdState(s, WallClock.nowNanos()));
            }
        });
    }

    /**
     * The debugger-safe robot: hold and release the robots, enable holds, the watchdog
     * (docs/debugging-robots.md). Holds are off unless enabled; then the relay is the plain byte copy.
     */
    public RobotHold holds() {
        return holds;
    }

    /**
     * Binds every listen address, then starts accepting. If one cannot be bound, none stays bound
     * and the exception names the address.
     */
    public synchronized void start() throws IOException {
        if (!servers.isEmpty() || closed) {
            throw new IllegalStateException("a spy starts once");
        }
        for (Route r : routes) {
            ServerSocket s = new ServerSocket();
            try {
                s.setReuseAddress(true);
                s.bind(r.listen(), 200);
            } catch (IOException e) {
                s.close();
                for (ServerSocket bound : servers) {
                    bound.close();
                }
                servers.clear();
                String why = e instanceof BindException ? "already in use or not allowed" : e.getMessage();
                throw new IOException("cannot listen on " + Route.text(r.listen()) + " (" + why + ")", e);
            }
            servers.add(s);
        }
        for (int i = 0; i < routes.size(); i++) {
            Route r = routes.get(i);
            ServerSocket s = servers.get(i);
            startThread("spy-accept-" + s.getLocalPort(), () -> acceptLoop(s, r));
        }
    }

    /** The addresses actually bound, in route order (useful with port 0). */
    public synchronized List<InetSocketAddress> boundAddresses() {
        return servers.stream().map(s -> (InetSocketAddress) s.getLocalSocketAddress()).toList();
    }

    public long bytesForwarded(Direction dir) {
        return (dir == Direction.CLIENT_TO_SERVER ? bytesC2S : bytesS2C).sum();
    }

    public int openConnections() {
        return relays.size();
    }

    public long totalConnections() {
        return connectionsTotal.sum();
    }

    /** Stops accepting and aborts the connections still open. */
    @Override
    public synchronized void close() {
        closed = true;
        for (ServerSocket s : servers) {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
        for (Relay r : relays) {
            r.abort("spy stopped");
        }
        holds.close();
    }

    private void acceptLoop(ServerSocket server, Route route) {
        while (!closed) {
            Socket client;
            try {
                client = server.accept();
            } catch (IOException e) {
                if (closed || server.isClosed()) {
                    return;
                }
                continue; // a failed accept (e.g. the client reset at once) concerns only that client
            }
            Relay relay = new Relay(client, route);
            relays.add(relay);
            connectionsTotal.increment();
            startThread("spy-c2s-" + relay.info.id(), relay::run);
        }
    }

    /** One robot program's connection and its upstream twin. */
    private final class Relay {
        final Socket client;
        final Socket upstream = new Socket();
        final Route route;
        final ConnectionInfo info;
        final AtomicInteger running = new AtomicInteger(2);
        /** The message-aware program-to-Player path when holds were enabled at accept; else null. */
        volatile HoldingForwarder holding;
        volatile String closeReason;

        Relay(Socket client, Route route) {
            this.client = client;
            this.route = route;
            InetSocketAddress local = (InetSocketAddress) client.getLocalSocketAddress();
            this.info = new ConnectionInfo(nextId.getAndIncrement(), local.getPort(),
                    Route.text((InetSocketAddress) client.getRemoteSocketAddress()), Route.text(local),
                    Route.text(route.upstream()));
        }

        void run() {
            observe(() -> observer.opened(info, WallClock.nowNanos()));
            try {
                client.setTcpNoDelay(true);
                upstream.setTcpNoDelay(true);
                upstream.connect(route.upstream(), CONNECT_TIMEOUT_MS);
            } catch (IOException e) {
                // The robot program already has a connection; resetting it is the closest to
                // what a direct connect to a closed port shows.
                resetQuietly(client);
                closeQuietly(upstream);
                finish("upstream " + info.upstream() + " refused: " + e.getMessage());
                return;
            }
            try {
                holding = holds.attach(info, upstream.getOutputStream());
            } catch (IOException e) {
                holding = null; // the upstream is already gone: the pumps see it and end the connection
            }
            startThread("spy-s2c-" + info.id(), () -> pump(upstream, client, Direction.SERVER_TO_CLIENT));
            pump(client, upstream, Direction.CLIENT_TO_SERVER);
        }

        void pump(Socket from, Socket to, Direction dir) {
            byte[] buf = new byte[BUFFER];
            LongAdder counter = dir == Direction.CLIENT_TO_SERVER ? bytesC2S : bytesS2C;
            HoldingForwarder hold = dir == Direction.CLIENT_TO_SERVER ? holding : null;
            try {
                InputStream in = from.getInputStream();
                OutputStream out = to.getOutputStream();
                while (true) {
                    int n = in.read(buf);
                    if (n < 0) {
                        if (hold != null) {
                            hold.end();
                        }
                        // orderly end of this direction: pass the half-close on
                        if (!to.isClosed()) {
                            to.shutdownOutput();
                        }
                        break;
                    }
                    if (hold != null) {
                        hold.relay(buf, 0, n); // whole messages only may be held or injected
                    } else {
                        out.write(buf, 0, n);
                    }
                    counter.add(n);
                    observe(() -> observer.chunk(info, dir, Arrays.copyOf(buf, n), WallClock.nowNanos()));
                }
            } catch (IOException e) {
                abort((dir == Direction.CLIENT_TO_SERVER ? "client" : "upstream") + " side failed: " + e.getMessage());
            }
            if (running.decrementAndGet() == 0) {
                closeQuietly(client);
                closeQuietly(upstream);
                finish(closeReason != null ? closeReason : "closed");
            }
        }

        /** A reset or error on one side resets the other, as the end-to-end connection would be. */
        void abort(String reason) {
            if (closeReason == null) {
                closeReason = reason;
            }
            resetQuietly(client);
            resetQuietly(upstream);
        }

        void finish(String reason) {
            relays.remove(this);
            holds.detach(holding);
            observe(() -> observer.closed(info, WallClock.nowNanos(), reason));
        }
    }

    /** An observer bug must never stop the bytes: it is counted and the relay goes on. */
    private void observe(Runnable call) {
        try {
            call.run();
        } catch (RuntimeException e) {
            observerFailures.increment();
        }
    }

    /** How often the observer threw (it must not; the wire went on regardless). */
    public long observerFailures() {
        return observerFailures.sum();
    }

    private static void resetQuietly(Socket s) {
        try {
            if (!s.isClosed()) {
                s.setSoLinger(true, 0);
            }
        } catch (SocketException ignored) {
            // not connected: plain close below
        }
        closeQuietly(s);
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // nothing left to do
        }
    }
}
