package org.stagecraft.spy.proxy;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.breakpoint.BreakpointGate;
import org.stagecraft.spy.breakpoint.DataBreakpoints;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldObserver;
import org.stagecraft.spy.hold.WorldChange;
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
     * How long a robot program's connection waits for Player when Player does not listen yet: a
     * program started together with Player often connects first, and libplayerc dies of SIGPIPE on
     * a reset instead of reporting it.
     */
    public static final Duration DEFAULT_UPSTREAM_GRACE = Duration.ofSeconds(5);
    /** Pause between connect attempts during the grace period: a refusal comes back at once. */
    private static final long RETRY_INTERVAL_MS = 100;
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
    private volatile WireObserver observer;
    private volatile Duration upstreamGrace = DEFAULT_UPSTREAM_GRACE;
    private final List<SpyListener> listeners = new CopyOnWriteArrayList<>();
    /** Opens on close(): ends the waits between connect attempts at once. */
    private final CountDownLatch stopped = new CountDownLatch(1);
    private boolean accepting;
    private final List<ServerSocket> servers = new ArrayList<>();
    private final Set<Relay> relays = ConcurrentHashMap.newKeySet();
    private final AtomicInteger nextId = new AtomicInteger(1);
    private final LongAdder bytesC2S = new LongAdder();
    private final LongAdder bytesS2C = new LongAdder();
    private final LongAdder connectionsTotal = new LongAdder();
    private final LongAdder observerFailures = new LongAdder();
    private final java.util.concurrent.atomic.AtomicLong lastFailureReport = new java.util.concurrent.atomic.AtomicLong(Long.MIN_VALUE);
    private volatile boolean closed;
    private final RobotHold holds;
    private final DataBreakpoints breakpoints;

    public NetworkSpy(List<Route> routes, WireObserver observer) {
        if (routes.isEmpty()) {
            throw new IllegalArgumentException("a spy needs at least one --listen/--to route");
        }
        this.routes = List.copyOf(routes);
        this.observer = observer;
        HoldObserver holdObserver = new HoldObserver() {
            @Override
            public void action(HoldAction a) {
                observe(() -> NetworkSpy.this.observer.holdAction(a, WallClock.nowNanos()));
            }

            @Override
            public void state(HoldState s) {
                observe(() -> NetworkSpy.this.observer.holdState(s, WallClock.nowNanos()));
            }
        };
        this.holds = new RobotHold(holdObserver);
        this.breakpoints = new DataBreakpoints(holds, holdObserver);
    }

    /**
     * Robot data breakpoints: stop when what Player sends satisfies a condition
     * (docs/debugging-robots.md). Off unless enabled; then the Player-to-program direction is the plain
     * byte copy.
     */
    public DataBreakpoints dataBreakpoints() {
        return breakpoints;
    }

    /**
     * The debugger-safe robot: hold and release the robots, enable holds, the watchdog
     * (docs/debugging-robots.md). Holds are off unless enabled; then the relay is the plain byte copy.
     */
    public RobotHold holds() {
        return holds;
    }

    /**
     * Logs and publishes that the session froze or thawed its simulated world (the session does that, the spy
     * only records it with its holds: docs/debugging-robots.md).
     */
    public void worldChanged(WorldChange change) {
        observe(() -> observer.worldChanged(change, WallClock.nowNanos()));
    }

    /**
     * How long each connection keeps trying to reach its upstream (Player) when it refuses, before
     * the robot program's connection is closed; {@link Duration#ZERO} tries once. Default
     * {@link #DEFAULT_UPSTREAM_GRACE}. May be changed at any time; a connection uses the value it
     * finds when it is accepted.
     */
    public NetworkSpy upstreamGrace(Duration grace) {
        if (grace.isNegative()) {
            throw new IllegalArgumentException("the upstream grace period cannot be negative: " + grace);
        }
        this.upstreamGrace = grace;
        return this;
    }

    public Duration upstreamGrace() {
        return upstreamGrace;
    }

    /** Replaces the observer given to the constructor; only before {@link #start()}. */
    public synchronized NetworkSpy observer(WireObserver o) {
        if (accepting) {
            throw new IllegalStateException("the observer is set before the spy starts");
        }
        this.observer = o;
        return this;
    }

    /** Adds a listener for {@link SpyNotice}s (Player refusing connections). */
    public NetworkSpy addListener(SpyListener l) {
        listeners.add(l);
        return this;
    }

    public void removeListener(SpyListener l) {
        listeners.remove(l);
    }

    /**
     * Binds every listen address without accepting yet, so a caller can learn that a port is taken
     * before it creates anything (a log file) for the session. If one cannot be bound, none stays
     * bound and the exception names the address and why. {@link #start()} binds too if this was
     * not called.
     */
    public synchronized void bind() throws IOException {
        if (!servers.isEmpty() || closed) {
            throw new IllegalStateException("a spy binds once");
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
                throw new IOException("cannot listen on " + Route.text(r.listen()) + " ("
                        + BindFailure.explain(r.listen(), e) + ")", e);
            }
            servers.add(s);
        }
    }

    /** Binds (unless {@link #bind()} did) and starts accepting on every route. */
    public synchronized void start() throws IOException {
        if (accepting || closed) {
            throw new IllegalStateException("a spy starts once");
        }
        if (servers.isEmpty()) {
            bind();
        }
        accepting = true;
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
        stopped.countDown();
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
        breakpoints.close();
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
        volatile Socket upstream = new Socket();
        final Route route;
        final ConnectionInfo info;
        final AtomicInteger running = new AtomicInteger(2);
        /** The message-aware program-to-Player path when holds were enabled at accept; else null. */
        volatile @Nullable HoldingForwarder holding;
        /** The message-aware Player-to-program path when data breakpoints were enabled at accept; else null. */
        volatile @Nullable BreakpointGate gate;
        volatile @Nullable String closeReason;

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
            String refused = connectUpstream();
            if (refused != null) {
                // The robot program already has a connection; resetting it is the closest to
                // what a direct connect to a closed port shows.
                resetQuietly(client);
                closeQuietly(upstream);
                finish("upstream " + info.upstream() + " refused: " + refused);
                return;
            }
            try {
                holding = holds.attach(info, upstream.getOutputStream());
                gate = breakpoints.attach(info, client.getOutputStream());
            } catch (IOException e) {
                holding = null; // a side is already gone: the pumps see it and end the connection
                gate = null;
            }
            startThread("spy-s2c-" + info.id(), () -> pump(upstream, client, Direction.SERVER_TO_CLIENT));
            pump(client, upstream, Direction.CLIENT_TO_SERVER);
        }

        /**
         * Connects to the upstream, retrying while it refuses until the grace period is over. The
         * robot program's bytes wait meanwhile in its socket's receive buffer, so nothing is lost
         * or reordered. Returns null once connected, else the last refusal.
         */
        @Nullable String connectUpstream() {
            long started = System.nanoTime();
            long graceNanos = upstreamGrace.toNanos();
            boolean waited = false;
            while (true) {
                Socket attempt = new Socket(); // a failed connect closes its socket: a new one per attempt
                upstream = attempt;
                IOException failure;
                try {
                    client.setTcpNoDelay(true);
                    attempt.setTcpNoDelay(true);
                    attempt.connect(route.upstream(), CONNECT_TIMEOUT_MS);
                    if (waited) {
                        double secs = (System.nanoTime() - started) / 1e9;
                        notice(SpyNotice.Kind.UPSTREAM_REACHED, String.format(Locale.ROOT,
                                "Player at %s accepted connection %d from %s after %.1f s", info.upstream(), info.id(),
                                info.client(), secs));
                    }
                    return null;
                } catch (IOException e) {
                    failure = e;
                    closeQuietly(attempt);
                }
                String why = failure.getMessage() == null ? failure.getClass().getSimpleName() : failure.getMessage();
                if (closed) {
                    return "spy stopped while waiting for the upstream (" + why + ")";
                }
                boolean graceLeft = System.nanoTime() - started + RETRY_INTERVAL_MS * 1_000_000 < graceNanos;
                if (!graceLeft) {
                    notice(SpyNotice.Kind.UPSTREAM_REFUSED, "Player at " + info.upstream() + " refused connection "
                            + info.id() + " from " + info.client() + " (" + why + ")"
                            + (graceNanos > 0 ? " for " + seconds(upstreamGrace) + " s" : "")
                            + "; the robot program's connection was closed. Is Player running and listening on "
                            + info.upstream() + "?");
                    return why;
                }
                if (!waited) {
                    waited = true;
                    notice(SpyNotice.Kind.UPSTREAM_WAITING, "Player at " + info.upstream() + " refused connection "
                            + info.id() + " from " + info.client() + " (" + why + "); retrying for up to "
                            + seconds(upstreamGrace) + " s");
                }
                try {
                    stopped.await(RETRY_INTERVAL_MS, TimeUnit.MILLISECONDS); // close() cuts the pause short
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return why;
                }
            }
        }

        void notice(SpyNotice.Kind kind, String text) {
            SpyNotice n = new SpyNotice(info, kind, text);
            observe(() -> observer.notice(n, WallClock.nowNanos()));
            for (SpyListener l : listeners) {
                observe(() -> l.notice(n));
            }
        }

        void pump(Socket from, Socket to, Direction dir) {
            byte[] buf = new byte[BUFFER];
            LongAdder counter = dir == Direction.CLIENT_TO_SERVER ? bytesC2S : bytesS2C;
            HoldingForwarder hold = dir == Direction.CLIENT_TO_SERVER ? holding : null;
            BreakpointGate breaks = dir == Direction.SERVER_TO_CLIENT ? gate : null;
            try {
                InputStream in = from.getInputStream();
                OutputStream out = to.getOutputStream();
                while (true) {
                    int n = in.read(buf);
                    if (n < 0) {
                        if (hold != null) {
                            hold.end();
                        }
                        if (breaks != null) {
                            breaks.end();
                        }
                        // orderly end of this direction: pass the half-close on
                        if (!to.isClosed()) {
                            to.shutdownOutput();
                        }
                        break;
                    }
                    if (hold != null) {
                        hold.relay(buf, 0, n); // whole messages only may be held or injected
                    } else if (breaks != null) {
                        breaks.relay(buf, 0, n); // may wait at a breakpoint's message until it is passed on
                    } else {
                        out.write(buf, 0, n);
                    }
                    counter.add(n);
                    observeChunk(info, dir, buf, n);
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

    /** Hands a forwarded chunk to the observer, in the relay's buffer (see WireObserver's contract). */
    private void observeChunk(ConnectionInfo info, Direction dir, byte[] buf, int n) {
        try {
            observer.chunk(info, dir, buf, 0, n, WallClock.nowNanos());
        } catch (Throwable e) {
            observerFailed(info, e);
        }
    }

    /**
     * An observer's failure (a bug, a missing class, memory) must never stop the bytes: it is
     * counted, reported to the listeners at once, and the relay goes on.
     */
    private void observe(Runnable call) {
        try {
            call.run();
        } catch (Throwable e) {
            observerFailed(null, e);
        }
    }

    private void observerFailed(@Nullable ConnectionInfo info, Throwable e) {
        observerFailures.increment();
        long now = System.nanoTime();
        long last = lastFailureReport.get();
        if (last != Long.MIN_VALUE && now - last < 1_000_000_000L || !lastFailureReport.compareAndSet(last, now)) {
            return; // reported at most once a second; the count goes on
        }
        String m = e.getMessage();
        SpyNotice n = new SpyNotice(info == null ? new ConnectionInfo(0, 0, "", "", "") : info,
                SpyNotice.Kind.OBSERVATION_FAILED, "the spy's observer failed" + (info == null ? "" : " on connection "
                        + info.id()) + " (" + e.getClass().getName() + (m == null ? "" : ": " + m) + "); forwarding goes on ["
                        + observerFailures.sum() + " observer failures so far]");
        for (SpyListener l : listeners) {
            try {
                l.notice(n);
            } catch (Throwable ignored) {
                // a listener's failure must not reach the wire either
            }
        }
    }

    /** How often the observer threw (it must not; the wire went on regardless). */
    public long observerFailures() {
        return observerFailures.sum();
    }

    private static String seconds(Duration d) {
        double s = d.toMillis() / 1000.0;
        return s == Math.rint(s) ? String.valueOf((long) s) : String.valueOf(s);
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
