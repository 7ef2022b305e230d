package org.stagecraft.scene;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * The newest message of every stream a layer's pattern matches. The bus delivers latest-value, so a
 * busy view never builds a backlog; this keeps one slot per stream and a frame takes whatever is newest
 * when it starts. A renderer therefore draws the present or nothing, never a queue of stale frames.
 */
public final class LayerFeed implements AutoCloseable {
    private static final Comparator<StreamMessage> BY_KEY = Comparator.comparing(m -> m.key().toString());

    private final Map<StreamKey, StreamMessage> latest = new ConcurrentHashMap<>();
    private final AtomicLong version = new AtomicLong();
    private final Runnable onChange;
    private final java.util.Queue<StreamMessage> unseen = new java.util.concurrent.ConcurrentLinkedQueue<>();
    private volatile boolean keepAll;
    private volatile @Nullable Subscription subscription;

    /** @param onChange told (on a bus thread) after each new message, e.g. to request a redraw */
    public LayerFeed(Runnable onChange) {
        this.onChange = onChange;
    }

    /** Subscribes (latest-value) to {@code pattern} on {@code bus}; an earlier subscription is closed. */
    public LayerFeed subscribe(StreamBus bus, StreamPattern pattern) {
        return subscribe(bus, pattern, DeliveryPolicy.latestValue());
    }

    /**
     * Subscribes with another policy. With a lossless policy every message is also kept until
     * {@link #drainUnseen()} takes it: for renderers that accumulate (map tiles), not for those that show
     * the present.
     */
    public LayerFeed subscribe(StreamBus bus, StreamPattern pattern, DeliveryPolicy policy) {
        close();
        keepAll = policy.isLossless();
        // a view opened late shows the last known state at once (e.g. while the program is suspended and
        // nothing new comes); seeded before subscribing, so anything newer replaces it. A message published
        // between the two is missed until its stream's next one.
        LastMessages.find(bus).ifPresent(store -> seed(store.matching(pattern)));
        subscription = bus.subscribe(pattern, policy, this::accept);
        return this;
    }

    private void seed(List<StreamMessage> known) {
        if (known.isEmpty()) {
            return;
        }
        for (StreamMessage m : known) {
            latest.put(m.key(), m);
        }
        version.incrementAndGet();
        onChange.run();
    }

    /** Messages accepted since the last call, oldest first (only kept for lossless subscriptions). */
    public List<StreamMessage> drainUnseen() {
        List<StreamMessage> out = new ArrayList<>();
        for (StreamMessage m = unseen.poll(); m != null; m = unseen.poll()) {
            out.add(m);
        }
        return out;
    }

    /** Takes one message (the bus consumer; tests and replays may call it directly). */
    public void accept(StreamMessage m) {
        latest.put(m.key(), m);
        if (keepAll) {
            unseen.add(m);
        }
        version.incrementAndGet();
        onChange.run();
    }

    /** Drops the streams {@code which} matches (an earlier session's robots); true if any was dropped. */
    public boolean forget(java.util.function.Predicate<StreamKey> which) {
        boolean any = latest.keySet().removeIf(which);
        if (any) {
            version.incrementAndGet();
        }
        return any;
    }

    /** The newest message of each stream, in key order (so frames are deterministic). */
    public List<StreamMessage> snapshot() {
        List<StreamMessage> out = new ArrayList<>(latest.values());
        out.sort(BY_KEY);
        return out;
    }

    /** Incremented by each accepted message. */
    public long version() {
        return version.get();
    }

    /** Messages the bus replaced before this feed took them (the frames it skipped to stay current). */
    public long dropped() {
        Subscription s = subscription;
        return s == null ? 0 : s.dropped();
    }

    @Override
    public void close() {
        Subscription s = subscription;
        subscription = null;
        if (s != null) {
            s.close();
        }
    }
}
