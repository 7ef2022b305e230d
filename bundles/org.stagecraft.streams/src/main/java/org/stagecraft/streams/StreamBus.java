package org.stagecraft.streams;

import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Consumer;

/**
 * Connects publishers of {@link StreamMessage}s (the Network Spy's decode thread, replay, stream
 * processors) with consumers (views, the logger, processors).
 *
 * <p>
 * Streams are conceptual: a stream exists from the first message published with its {@link StreamKey}.
 * Consumers subscribe with a {@link StreamPattern}, before or after matching streams appear, and pick a
 * {@link DeliveryPolicy}. {@link #publish(StreamMessage)} never blocks and never runs a consumer on the
 * publisher's thread (unless the bus was given a same-thread executor): it looks up the subscriptions
 * matching the key in a per-key cache (rebuilt lazily after every subscribe or unsubscribe), puts the
 * message into each one's bounded buffer and, if that subscription's drain task is not already pending,
 * hands one to the delivery executor. Each subscription has at most one drain task at a time, so a
 * consumer sees its messages one at a time and in publish order within a stream; a slow consumer only
 * fills (and overflows) its own buffer, a throwing one only increments its own failure count.
 *
 * <p>
 * Thread-safe. Publishing from several threads is allowed; order is defined per publishing thread.
 */
public final class StreamBus implements AutoCloseable {

    /** A listener registration; closing it stops further notifications. */
    public interface Registration extends AutoCloseable {
        @Override
        void close();
    }

    /** Messages one drain task delivers before it yields its thread (keeps e.g. the UI thread responsive). */
    static final int BATCH = 256;

    private final Executor executor;
    private final ExecutorService owned;
    private final CopyOnWriteArrayList<BusSubscription> subscriptions = new CopyOnWriteArrayList<>();
    /** Matching subscriptions per key; replaced (not cleared) on every change, so no stale entry survives. */
    private volatile ConcurrentHashMap<StreamKey, BusSubscription[]> routes = new ConcurrentHashMap<>();
    private final ConcurrentHashMap<StreamKey, Boolean> known = new ConcurrentHashMap<>();
    private final CopyOnWriteArrayList<StreamListener> listeners = new CopyOnWriteArrayList<>();
    private final LongAdder published = new LongAdder();
    private final LongAdder listenerFailures = new LongAdder();
    private volatile boolean closed;

    /** A bus delivering on virtual threads of its own (one drain task per subscription at a time). */
    public StreamBus() {
        this.owned = Executors.newThreadPerTaskExecutor(Thread.ofVirtual().name("stream-bus-", 0).factory());
        this.executor = owned;
    }

    /**
     * A bus delivering through {@code deliveryExecutor}, e.g. {@code Runnable::run} for deterministic
     * tests (then consumers run on the publisher's thread and can slow it down) or an SWT display's
     * {@code asyncExec} for views (at most one pending runnable per subscription).
     */
    public StreamBus(Executor deliveryExecutor) {
        this.executor = Objects.requireNonNull(deliveryExecutor, "deliveryExecutor");
        this.owned = null;
    }

    /**
     * Offers {@code m} to every subscription whose pattern matches its key. Never blocks: buffers are
     * bounded and overflow is counted per subscription. Ignored after {@link #close()}.
     */
    public void publish(StreamMessage m) {
        StreamKey key = m.key();
        if (closed) {
            return;
        }
        published.increment();
        ConcurrentHashMap<StreamKey, BusSubscription[]> table = routes;
        BusSubscription[] route = table.get(key);
        if (route == null) {
            if (known.putIfAbsent(key, Boolean.TRUE) == null) {
                announce(key);
            }
            route = routeFor(key);
            table.putIfAbsent(key, route);
        }
        for (BusSubscription s : route) {
            s.offer(m);
        }
    }

    /**
     * Subscribes {@code consumer} to every stream, present or future, matching {@code pattern}.
     *
     * @throws IllegalStateException if the bus is closed
     */
    public Subscription subscribe(StreamPattern pattern, DeliveryPolicy policy, StreamConsumer consumer) {
        Objects.requireNonNull(pattern, "pattern");
        Objects.requireNonNull(policy, "policy");
        Objects.requireNonNull(consumer, "consumer");
        if (closed) {
            throw new IllegalStateException("stream bus is closed");
        }
        BusSubscription s = new BusSubscription(this, pattern, policy, consumer);
        subscriptions.add(s);
        routes = new ConcurrentHashMap<>(); // after the add: a publisher that sees the new table sees s
        if (closed) {
            s.close();
        }
        return s;
    }

    void unsubscribe(BusSubscription s) {
        if (subscriptions.remove(s)) {
            routes = new ConcurrentHashMap<>();
        }
    }

    private BusSubscription[] routeFor(StreamKey key) {
        return subscriptions.stream().filter(s -> s.pattern().matches(key)).toArray(BusSubscription[]::new);
    }

    /** Every stream seen so far (a snapshot). */
    public Set<StreamKey> streams() {
        return Set.copyOf(known.keySet());
    }

    /**
     * Tells {@code listener} once about every stream first published after this call, through the
     * delivery executor (never on the publisher's thread unless the executor is a same-thread one).
     */
    public Registration onNewStream(Consumer<StreamKey> listener) {
        return onNewStream(listener, false);
    }

    /**
     * As {@link #onNewStream(Consumer)}; with {@code includeExisting} it is also told about every stream
     * seen before, so that {@code streams()} plus notifications cover all streams without a gap. Each key
     * is told at most once.
     */
    public Registration onNewStream(Consumer<StreamKey> listener, boolean includeExisting) {
        Objects.requireNonNull(listener, "listener");
        StreamListener l = new StreamListener(listener);
        listeners.add(l);
        if (includeExisting) {
            for (StreamKey k : known.keySet()) {
                tell(l, k);
            }
        }
        return () -> {
            l.closed = true;
            listeners.remove(l);
        };
    }

    private void announce(StreamKey key) {
        for (StreamListener l : listeners) {
            tell(l, key);
        }
    }

    private void tell(StreamListener l, StreamKey key) {
        if (l.closed || closed || l.told.putIfAbsent(key, Boolean.TRUE) != null) {
            return;
        }
        try {
            executor.execute(() -> {
                if (l.closed || closed) {
                    return;
                }
                try {
                    l.listener.accept(key);
                } catch (Throwable t) {
                    listenerFailures.increment();
                }
            });
        } catch (RuntimeException rejected) {
            listenerFailures.increment();
        }
    }

    /** Messages published so far (before {@link #close()}). */
    public long published() {
        return published.sum();
    }

    /** Exceptions thrown by new-stream listeners (or notifications the executor rejected). */
    public long listenerFailures() {
        return listenerFailures.sum();
    }

    /** Number of open subscriptions. */
    public int subscriptionCount() {
        return subscriptions.size();
    }

    public boolean isClosed() {
        return closed;
    }

    Executor executor() {
        return executor;
    }

    /**
     * Stops delivery: closes every subscription, forgets the listeners, ignores later publishes and, for a
     * bus with its own threads, interrupts consumers still running. Idempotent.
     */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        for (BusSubscription s : subscriptions) {
            s.close();
        }
        subscriptions.clear();
        routes = new ConcurrentHashMap<>();
        for (StreamListener l : listeners) {
            l.closed = true;
        }
        listeners.clear();
        if (owned != null) {
            owned.shutdownNow();
        }
    }

    private static final class StreamListener {
        final Consumer<StreamKey> listener;
        final ConcurrentHashMap<StreamKey, Boolean> told = new ConcurrentHashMap<>();
        volatile boolean closed;

        StreamListener(Consumer<StreamKey> listener) {
            this.listener = listener;
        }
    }
}
