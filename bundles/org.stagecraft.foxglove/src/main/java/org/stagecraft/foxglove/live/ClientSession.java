package org.stagecraft.foxglove.live;

import java.nio.ByteBuffer;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

import org.eclipse.jdt.annotation.Nullable;
import org.java_websocket.WebSocket;
import org.java_websocket.WebSocketImpl;
import org.java_websocket.exceptions.WebsocketNotConnectedException;

/**
 * One connected viewer: its subscriptions and its bounded queue. Frames wait for the viewer in the
 * WebSocket library's outgoing queue of the connection, written by the library's selector thread as
 * the viewer's TCP window allows; a message frame is only added while fewer than {@code maxQueuedFrames}
 * wait there, else it is dropped and counted. So a viewer that reads slowly or not at all costs the
 * publisher one size check, and memory stays bounded.
 */
final class ClientSession {
    /** The status id under which drops are reported: each new report replaces the previous one. */
    static final String DROPPED_STATUS_ID = "stagecraft.dropped";
    private static final long DROP_REPORT_INTERVAL_NANOS = 1_000_000_000L;

    private final WebSocket connection;
    private final int maxQueuedFrames;
    private final String name;
    /** channel id -> subscription id, and back; changed under the server's lock, read by publishers. */
    private final Map<Integer, Integer> subscriptionOfChannel = new ConcurrentHashMap<>();
    private final Map<Integer, Integer> channelOfSubscription = new ConcurrentHashMap<>();
    private final LongAdder sent = new LongAdder();
    private final LongAdder dropped = new LongAdder();
    private long droppedReported; // guarded by this
    private long lastReportNanos = System.nanoTime() - DROP_REPORT_INTERVAL_NANOS; // guarded by this

    ClientSession(WebSocket connection, int maxQueuedFrames) {
        this.connection = connection;
        this.maxQueuedFrames = maxQueuedFrames;
        this.name = connection.getRemoteSocketAddress() == null ? "viewer"
                : connection.getRemoteSocketAddress().getAddress().getHostAddress() + ":"
                        + connection.getRemoteSocketAddress().getPort();
    }

    String name() {
        return name;
    }

    long sent() {
        return sent.sum();
    }

    long dropped() {
        return dropped.sum();
    }

    /** Frames waiting to be written to the viewer. */
    int queued() {
        return connection instanceof WebSocketImpl impl ? impl.outQueue.size() : 0;
    }

    /** Protocol messages (serverInfo, advertise, status...): few and small, never dropped. */
    void sendText(String json) {
        try {
            connection.send(json);
        } catch (WebsocketNotConnectedException closing) {
            // the viewer is going: its onClose removes this session
        }
    }

    /** Message and time frames: dropped (and counted) while the viewer's queue is full. */
    boolean offer(ByteBuffer frame) {
        if (queued() >= maxQueuedFrames) {
            dropped.increment();
            return false;
        }
        try {
            connection.send(frame);
            sent.increment();
            return true;
        } catch (WebsocketNotConnectedException closing) {
            dropped.increment();
            return false;
        }
    }

    @Nullable Integer subscriptionOf(int channelId) {
        return subscriptionOfChannel.get(channelId);
    }

    /** @return why the subscription is refused, or null when it is made */
    @Nullable String subscribe(int subscriptionId, int channelId) {
        if (channelOfSubscription.containsKey(subscriptionId)) {
            return "subscription id " + Integer.toUnsignedString(subscriptionId) + " is already in use";
        }
        if (subscriptionOfChannel.containsKey(channelId)) {
            return "channel " + Integer.toUnsignedString(channelId) + " is already subscribed (subscription "
                    + Integer.toUnsignedString(subscriptionOfChannel.get(channelId)) + ")";
        }
        channelOfSubscription.put(subscriptionId, channelId);
        subscriptionOfChannel.put(channelId, subscriptionId);
        return null;
    }

    /** @return why not, or null when it is undone */
    @Nullable String unsubscribe(int subscriptionId) {
        @Nullable Integer channel = channelOfSubscription.remove(subscriptionId);
        if (channel == null) {
            return "no subscription " + Integer.toUnsignedString(subscriptionId);
        }
        subscriptionOfChannel.remove(channel);
        return null;
    }

    /** The channel has gone: its subscription with it. */
    void channelGone(int channelId) {
        @Nullable Integer sub = subscriptionOfChannel.remove(channelId);
        if (sub != null) {
            channelOfSubscription.remove(sub);
        }
    }

    /**
     * Tells the viewer, at most once a second and once its queue has room again, how many messages it
     * has missed so far.
     *
     * @return the new total reported, or -1 when nothing was reported
     */
    synchronized long reportDrops(long nowNanos) {
        long total = dropped.sum();
        if (total == droppedReported || nowNanos - lastReportNanos < DROP_REPORT_INTERVAL_NANOS
                || queued() >= maxQueuedFrames) {
            return -1;
        }
        droppedReported = total;
        lastReportNanos = nowNanos;
        sendText(LiveProtocol.status(LiveProtocol.WARNING, total + " messages were not sent to this viewer: it read"
                + " more slowly than the robots published (at most " + maxQueuedFrames + " wait for it)",
                DROPPED_STATUS_ID));
        return total;
    }
}
