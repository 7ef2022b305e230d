package org.stagecraft.foxglove.live;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.java_websocket.WebSocket;
import org.java_websocket.WebSocketImpl;
import org.java_websocket.drafts.Draft;
import org.java_websocket.drafts.Draft_6455;
import org.java_websocket.framing.CloseFrame;
import org.java_websocket.handshake.ClientHandshake;
import org.java_websocket.protocols.IProtocol;
import org.java_websocket.protocols.Protocol;
import org.java_websocket.server.WebSocketServer;
import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveSink;

/**
 * The live view: a WebSocket server speaking the Foxglove WebSocket protocol v1, fed as a
 * {@link FoxgloveSink}. Foxglove or Lichtblick connect to {@link #uri()}, are told the channels
 * (advertise, and unadvertise when a stream ends), subscribe, and receive each message of their
 * subscriptions as a binary frame.
 *
 * <p>{@link #publish} never waits for a viewer: each viewer has a bounded queue (see
 * {@link ClientSession}); what does not fit is dropped, counted ({@link #counters()}), told to the viewer
 * as a status message and to {@link #onNotice}. {@code advertise}, {@code unadvertise} and {@code publish}
 * may be called from any thread; the relay calls them from one.
 */
public final class FoxgloveServer implements FoxgloveSink, AutoCloseable {
    /** Per viewer, how many frames may wait to be written before new ones are dropped. */
    public static final int DEFAULT_MAX_QUEUED_FRAMES = 1024;
    /** Time messages are sent when the log time has moved on by at least this much. */
    static final long TIME_INTERVAL_NANOS = 50_000_000L;
    /**
     * Each viewer's socket send buffer. Fixed (the kernel would otherwise grow it to megabytes for a
     * viewer that does not read), so what waits for a viewer is bounded: its queue plus this.
     */
    static final int SEND_BUFFER_BYTES = 256 * 1024;
    private static final long START_TIMEOUT_SECONDS = 10;

    /**
     * What the server counted since it started.
     *
     * @param viewers       connected now
     * @param viewersServed connected since the start
     * @param framesDropped message and time frames not sent because a viewer's queue was full
     */
    public record Counters(int viewers, long viewersServed, int channels, long published, long framesSent,
            long framesDropped) {
    }

    private final String name;
    private final int maxQueuedFrames;
    private final String sessionId = Long.toString(System.currentTimeMillis());
    private final Endpoint endpoint;
    private final CompletableFuture<@Nullable Void> started = new CompletableFuture<>();
    private final Map<WebSocket, ClientSession> sessions = new ConcurrentHashMap<>();
    private final Object lock = new Object(); // orders channel changes, subscriptions and new viewers
    // guarded by lock
    private final Map<FoxgloveChannel, Integer> idOf = new HashMap<>(); // every channel ever: ids are reused for the same channel
    private final Map<Integer, FoxgloveChannel> advertised = new LinkedHashMap<>();
    /** Read by publishers without the lock. */
    private final Map<FoxgloveChannel, Integer> advertisedIds = new ConcurrentHashMap<>();
    private final LongAdder published = new LongAdder();
    private final LongAdder viewersServed = new LongAdder();
    private final LongAdder sentByGone = new LongAdder();
    private final LongAdder droppedByGone = new LongAdder();
    private final AtomicLong lastTimeSent = new AtomicLong(Long.MIN_VALUE);
    private volatile Consumer<String> notices = n -> {
    };

    private FoxgloveServer(InetSocketAddress address, String name, int maxQueuedFrames) {
        this.name = name;
        this.maxQueuedFrames = maxQueuedFrames;
        // Only foxglove.websocket.v1: a client that does not offer it is refused at the handshake.
        List<IProtocol> protocols = List.of(new Protocol(LiveProtocol.SUBPROTOCOL));
        this.endpoint = new Endpoint(address, List.of(new Draft_6455(Collections.emptyList(), protocols)));
    }

    /**
     * Binds and starts serving.
     *
     * @param address where to listen; port 0 picks a free one ({@link #address()} tells which)
     * @param name    the server's name in serverInfo (viewers may show it)
     * @throws IOException when the address cannot be bound, e.g. the port is in use
     */
    public static FoxgloveServer start(InetSocketAddress address, String name, int maxQueuedFrames) throws IOException {
        if (maxQueuedFrames < 1) {
            throw new IllegalArgumentException("maxQueuedFrames " + maxQueuedFrames + " < 1");
        }
        FoxgloveServer s = new FoxgloveServer(address, name, maxQueuedFrames);
        s.endpoint.setReuseAddr(true);
        s.endpoint.setTcpNoDelay(true);
        s.endpoint.start();
        try {
            s.started.get(START_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            s.stopQuietly();
            Throwable c = e.getCause();
            throw new IOException("cannot serve Foxglove on " + text(address) + ": "
                    + (c.getMessage() != null ? c.getMessage() : c.toString()), c);
        } catch (TimeoutException e) {
            s.stopQuietly();
            throw new IOException("cannot serve Foxglove on " + text(address) + ": not started after "
                    + START_TIMEOUT_SECONDS + " s", e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            s.stopQuietly();
            throw new IOException("interrupted while starting the Foxglove server", e);
        }
        return s;
    }

    public static FoxgloveServer start(InetSocketAddress address) throws IOException {
        return start(address, "Stagecraft", DEFAULT_MAX_QUEUED_FRAMES);
    }

    /** Where it listens (the real port when 0 was asked for). */
    public InetSocketAddress address() {
        return new InetSocketAddress(endpoint.getAddress().getAddress(), endpoint.getPort());
    }

    /** The address to give a viewer, e.g. {@code ws://127.0.0.1:8765}. */
    public URI uri() {
        InetSocketAddress a = address();
        // listening on every interface: this machine's viewers reach it as localhost
        String host = a.getAddress().isAnyLocalAddress() ? "localhost" : a.getAddress().getHostAddress();
        if (host.contains(":")) {
            host = "[" + host + "]";
        }
        return URI.create("ws://" + host + ":" + a.getPort());
    }

    /** Told, in one line each, of viewers coming and going, bad requests and dropped messages. */
    public void onNotice(Consumer<String> listener) {
        notices = Objects.requireNonNull(listener);
    }

    public Counters counters() {
        long sent = sentByGone.sum();
        long dropped = droppedByGone.sum();
        for (ClientSession s : sessions.values()) {
            sent += s.sent();
            dropped += s.dropped();
        }
        int channels;
        synchronized (lock) {
            channels = advertised.size();
        }
        return new Counters(sessions.size(), viewersServed.sum(), channels, published.sum(), sent, dropped);
    }

    // ---- FoxgloveSink ----------------------------------------------------------------------------

    @Override
    public void advertise(FoxgloveChannel channel) {
        synchronized (lock) {
            @Nullable Integer known = advertisedIds.get(channel);
            if (known != null) {
                return; // already advertised: nothing new for the viewers
            }
            int id = idOf.computeIfAbsent(channel, c -> idOf.size() + 1);
            advertised.put(id, channel);
            advertisedIds.put(channel, id);
            String msg = LiveProtocol.advertise(List.of(new LiveProtocol.Advertised(id, channel)));
            sessions.values().forEach(s -> s.sendText(msg));
        }
    }

    @Override
    public void unadvertise(FoxgloveChannel channel) {
        synchronized (lock) {
            @Nullable Integer id = advertisedIds.remove(channel);
            if (id == null) {
                return;
            }
            advertised.remove(id);
            String msg = LiveProtocol.unadvertise(List.of(id));
            for (ClientSession s : sessions.values()) {
                s.channelGone(id);
                s.sendText(msg);
            }
        }
    }

    /**
     * @throws IllegalStateException when the channel is not advertised: a converter bug
     */
    @Override
    public void publish(FoxgloveChannel channel, long logTimeNanos, long publishTimeNanos, byte[] json) {
        @Nullable Integer id = advertisedIds.get(channel);
        if (id == null) {
            throw new IllegalStateException("publish on " + channel.topic() + " before it was advertised");
        }
        published.increment();
        sendTime(logTimeNanos);
        long now = System.nanoTime();
        for (ClientSession s : sessions.values()) {
            Integer sub = s.subscriptionOf(id);
            if (sub != null) {
                s.offer(LiveProtocol.messageData(sub, logTimeNanos, json));
                long reported = s.reportDrops(now);
                if (reported > 0) {
                    notices.accept("viewer " + s.name() + " is too slow: " + reported + " messages dropped so far");
                }
            }
        }
    }

    /** The viewers' clock follows the log times of the messages, in steps of at least TIME_INTERVAL. */
    private void sendTime(long logTimeNanos) {
        long last = lastTimeSent.get();
        if (last != Long.MIN_VALUE && logTimeNanos - last < TIME_INTERVAL_NANOS) {
            return;
        }
        if (!lastTimeSent.compareAndSet(last, logTimeNanos)) {
            return; // another publisher just sent one
        }
        for (ClientSession s : sessions.values()) {
            s.offer(LiveProtocol.time(logTimeNanos));
        }
    }

    /**
     * Closes every viewer's connection and the listening socket. Each viewer's counts are told at once
     * ({@link #onNotice}): a viewer that does not read may never finish the closing handshake, so once
     * the server has stopped (at most a second), a connection still open is cut.
     */
    @Override
    public void close() {
        List<WebSocket> viewers = List.copyOf(endpoint.getConnections());
        for (WebSocket conn : List.copyOf(sessions.keySet())) {
            closed(conn, "Stagecraft stopped serving");
        }
        stopQuietly();
        // the server's thread has ended (or given up): nothing else would ever close these sockets
        for (WebSocket conn : viewers) {
            if (!conn.isClosed()) {
                conn.closeConnection(CloseFrame.GOING_AWAY, "Stagecraft stopped serving");
            }
        }
    }

    private void stopQuietly() {
        try {
            endpoint.stop(1000, "Stagecraft stopped serving");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    // ---- viewers ---------------------------------------------------------------------------------

    private void opened(WebSocket conn) {
        if (conn instanceof WebSocketImpl impl && impl.getChannel() instanceof SocketChannel socket) {
            try {
                socket.setOption(StandardSocketOptions.SO_SNDBUF, SEND_BUFFER_BYTES);
            } catch (IOException e) {
                notices.accept("cannot bound a viewer's send buffer: " + e.getMessage());
            }
        }
        ClientSession s = new ClientSession(conn, maxQueuedFrames);
        synchronized (lock) {
            s.sendText(LiveProtocol.serverInfo(name, sessionId, Map.of()));
            List<LiveProtocol.Advertised> now = new ArrayList<>();
            advertised.forEach((id, c) -> now.add(new LiveProtocol.Advertised(id, c)));
            s.sendText(LiveProtocol.advertise(now)); // always one, even with no channel yet
            sessions.put(conn, s);
        }
        viewersServed.increment();
        notices.accept("viewer " + s.name() + " connected");
    }

    private void closed(WebSocket conn, String reason) {
        @Nullable ClientSession s = sessions.remove(conn);
        if (s != null) {
            sentByGone.add(s.sent());
            droppedByGone.add(s.dropped());
            notices.accept("viewer " + s.name() + " disconnected" + (reason == null || reason.isBlank() ? "" : " (" + reason + ")")
                    + ": " + s.sent() + " frames sent, " + s.dropped() + " dropped");
        }
    }

    private void request(WebSocket conn, String text) {
        @Nullable ClientSession s = sessions.get(conn);
        if (s == null) {
            return;
        }
        LiveProtocol.Request r;
        try {
            r = LiveProtocol.parse(text);
        } catch (IllegalArgumentException e) {
            refuse(s, "bad request: " + e.getMessage());
            return;
        }
        switch (r) {
            case LiveProtocol.Subscribe sub -> {
                for (LiveProtocol.Subscription one : sub.subscriptions()) {
                    String problem;
                    synchronized (lock) {
                        problem = advertised.containsKey(one.channelId()) ? s.subscribe(one.id(), one.channelId())
                                : "no channel " + Integer.toUnsignedString(one.channelId());
                    }
                    if (problem != null) {
                        refuse(s, "subscribe: " + problem);
                    }
                }
            }
            case LiveProtocol.Unsubscribe un -> {
                for (int id : un.subscriptionIds()) {
                    String problem;
                    synchronized (lock) {
                        problem = s.unsubscribe(id);
                    }
                    if (problem != null) {
                        refuse(s, "unsubscribe: " + problem);
                    }
                }
            }
            case LiveProtocol.Unsupported u -> refuse(s, "'" + u.op() + "' is not supported by this server (capabilities: "
                    + LiveProtocol.CAPABILITIES + ")");
        }
    }

    private void refuse(ClientSession s, String problem) {
        s.sendText(LiveProtocol.status(LiveProtocol.ERROR, problem, null));
        notices.accept("viewer " + s.name() + ": " + problem);
    }

    private static String text(InetSocketAddress a) {
        return (a.getAddress() != null ? a.getAddress().getHostAddress() : a.getHostString()) + ":" + a.getPort();
    }

    /** The library's server, forwarding its callbacks (on its own threads). */
    private final class Endpoint extends WebSocketServer {
        Endpoint(InetSocketAddress address, List<Draft> drafts) {
            super(address, 1, drafts);
        }

        @Override
        public void onStart() {
            started.complete(null);
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void onOpen(WebSocket conn, ClientHandshake handshake) {
            opened(conn);
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void onClose(WebSocket conn, int code, String reason, boolean remote) {
            closed(conn, reason);
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void onMessage(WebSocket conn, String message) {
            request(conn, message);
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void onMessage(WebSocket conn, ByteBuffer message) {
            @Nullable ClientSession s = sessions.get(conn);
            if (s != null) {
                refuse(s, "binary client messages are not supported by this server (no clientPublish)");
            }
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void onError(WebSocket conn, Exception ex) {
            if (conn == null && !started.isDone()) {
                started.completeExceptionally(ex); // could not bind
            } else {
                ClientSession s = conn == null ? null : sessions.get(conn);
                notices.accept((s != null ? "viewer " + s.name() + ": " : "Foxglove server: ") + ex.getMessage());
            }
        }
    }
}
