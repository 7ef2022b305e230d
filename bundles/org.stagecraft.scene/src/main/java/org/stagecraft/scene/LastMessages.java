package org.stagecraft.scene;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * The newest message of every stream a bus has carried, for subscribers that come late. The bus itself
 * only delivers what is published after a subscription; a view opened while the robot program is
 * suspended in the debugger would then draw nothing, because a suspended program asks for no data and
 * Player's pushes stop once the program's socket is full. Every view of the bus starts from these.
 *
 * <p>Lives with the bus's {@link SharedWorld} (created at workbench start). Bounded: the streams used least
 * recently are forgotten beyond {@link #MAX_STREAMS} (keys include each connection's client port, so a long
 * workbench life sees many).
 */
public final class LastMessages implements AutoCloseable {
    public static final int MAX_STREAMS = 4096;
    private static final Map<StreamBus, LastMessages> STORES = new IdentityHashMap<>();

    private final Map<StreamKey, StreamMessage> latest = new LinkedHashMap<>(256, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.@Nullable Entry<StreamKey, StreamMessage> eldest) {
            return size() > MAX_STREAMS;
        }
    };
    private final Subscription subscription;

    private LastMessages(StreamBus bus) {
        // latest-value: the store never lags, and a burst costs it one message per stream
        subscription = bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), this::accept);
    }

    /** The bus's store, created (and subscribed) on first use. */
    public static synchronized LastMessages of(StreamBus bus) {
        STORES.entrySet().removeIf(e -> e.getKey().isClosed() && closeStore(e.getValue()));
        return STORES.computeIfAbsent(bus, LastMessages::new);
    }

    /** The bus's store if someone made one (views seed from it; a bus without one has no history to give). */
    public static synchronized Optional<LastMessages> find(StreamBus bus) {
        return Optional.ofNullable(STORES.get(bus));
    }

    private static boolean closeStore(LastMessages s) {
        s.close();
        return true;
    }

    private void accept(StreamMessage m) {
        synchronized (latest) {
            latest.put(m.key(), m);
        }
    }

    /** The newest message of each stream {@code pattern} matches. */
    public List<StreamMessage> matching(StreamPattern pattern) {
        List<StreamMessage> out = new ArrayList<>();
        synchronized (latest) {
            for (StreamMessage m : latest.values()) {
                if (pattern.matches(m.key())) {
                    out.add(m);
                }
            }
        }
        return out;
    }

    /** Forgets the streams {@code which} matches (an earlier session's robots, see {@link WorldModel#forgotten}). */
    public void forget(java.util.function.Predicate<StreamKey> which) {
        synchronized (latest) {
            latest.keySet().removeIf(which);
        }
    }

    public int streams() {
        synchronized (latest) {
            return latest.size();
        }
    }

    @Override
    public void close() {
        subscription.close();
    }
}
