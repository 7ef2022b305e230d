package org.stagecraft.foxglove.live;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveSink;

/**
 * Between the converter and the server: remembers which connections fed each channel, so that when a
 * robot program's connection ends the channels only it fed are unadvertised (its robot has left the
 * viewers' topic list); a channel that gets messages again is advertised again. The converter itself
 * advertises a channel once, forever. Used from one thread (the relay's consumer).
 */
final class LiveChannels implements FoxgloveSink {
    /** Messages that come from no connection (e.g. session events). */
    static final int NO_CONNECTION = -1;

    private final FoxgloveSink server;
    private final Map<FoxgloveChannel, Set<Integer>> feeders = new HashMap<>();
    private final Set<FoxgloveChannel> ended = new HashSet<>();
    private int current = NO_CONNECTION;

    LiveChannels(FoxgloveSink server) {
        this.server = server;
    }

    /** The connection of the bus message being converted. */
    void converting(int connectionId) {
        current = connectionId;
    }

    /** Unadvertises the channels that no other open connection fed. */
    void connectionEnded(int connectionId) {
        for (var e : feeders.entrySet()) {
            Set<Integer> by = e.getValue();
            if (by.remove(connectionId) && by.isEmpty() && ended.add(e.getKey())) {
                server.unadvertise(e.getKey());
            }
        }
    }

    @Override
    public void advertise(FoxgloveChannel channel) {
        feeders.computeIfAbsent(channel, c -> new HashSet<>());
        ended.remove(channel);
        server.advertise(channel);
    }

    @Override
    public void publish(FoxgloveChannel channel, long logTimeNanos, long publishTimeNanos, byte[] json) {
        if (ended.remove(channel)) {
            server.advertise(channel); // its robot is back
        }
        if (current != NO_CONNECTION) {
            feeders.computeIfAbsent(channel, c -> new HashSet<>()).add(current);
        }
        server.publish(channel, logTimeNanos, publishTimeNanos, json);
    }

    @Override
    public void unadvertise(FoxgloveChannel channel) {
        feeders.remove(channel);
        ended.remove(channel);
        server.unadvertise(channel);
    }
}
