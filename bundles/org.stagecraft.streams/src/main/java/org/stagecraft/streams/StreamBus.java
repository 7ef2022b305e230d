package org.stagecraft.streams;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.BiConsumer;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.Nullable;

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
    private final @Nullable ExecutorService owned;
    private final CopyOnWriteArrayList<BusSubscription> subscriptions = new CopyOnWriteArrayList<>();
    /** Matching subscriptions per key; replaced (not cleared) on every change, so no stale entry survives. */
    private volatile ConcurrentHashMap<StreamKey, BusSubscription[]> routes = new ConcurrentHashMap<>();
    private final ConcurrentHashMap<StreamKey, Boolean> known = new ConcurrentHashMap<>();
    /**
     * The known streams by address (source and destination), so that {@link #release(String)} finds a
     * connection's streams without scanning all of them. Guarded by {@code streamLock}, as are the
     * additions to {@code known}: a stream is learned or released under it, never half of each.
     */
    private final HashMap<String, Set<StreamKey>> byAddress = new HashMap<>();
    private final Object streamLock = new Object();
    private final CopyOnWriteArrayList<StreamListener> listeners = new CopyOnWriteArrayList<>();
    private final CopyOnWriteArrayList<ReleaseListener> releaseListeners = new CopyOnWriteArrayList<>();
    private final LongAdder released = new LongAdder();
    private final LongAdder published = new LongAdder();
    private final LongAdder listenerFailures = new LongAdder();
    private volatile boolean closed;

    /**
     * A bus delivering on daemon threads of its own (one drain task per subscription at a time): a
     * pool that reuses its idle threads for a while ({@value #IDLE_SECONDS} s) and ends them after,
     * and adds one whenever none is idle, so that no consumer waits for another. Not a virtual
     * thread per drain task, as before: at a robot's rates a drain task is due for every few
     * messages, and starting a virtual thread each time (and the carriers' search for work after it)
     * cost the spy's process more CPU than observing the messages.
     */
    public StreamBus() {
        ExecutorService own = new ThreadPoolExecutor(0, Integer.MAX_VALUE, IDLE_SECONDS, TimeUnit.SECONDS,
                new SynchronousQueue<>(), Thread.ofPlatform().daemon().name("stream-bus-", 0).factory());
        this.owned = own;
        this.executor = own;
    }

    /** How long an idle delivery thread of the default bus waits for the next drain task before it ends. */
    static final int IDLE_SECONDS = 30;

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
        for (BusSubscription s : route(key)) {
            s.offer(m);
        }
    }

    /** The subscriptions whose patterns match {@code key}, learnt once per key. */
    private BusSubscription[] route(StreamKey key) {
        ConcurrentHashMap<StreamKey, BusSubscription[]> table = routes;
        BusSubscription @Nullable [] route = table.get(key);
        return route != null ? route : learn(key, table);
    }

    /**
     * Offers {@code messages}, in order, as {@link #publish} would one by one, but hands each
     * subscription at most one drain task for all of them: a publisher with many messages at once
     * (the spy's observation thread, once per round) wakes each consumer once instead of once per
     * message. Never blocks.
     */
    public void publishAll(List<StreamMessage> messages) {
        if (closed || messages.isEmpty()) {
            return;
        }
        published.add(messages.size());
        List<BusSubscription> due = new ArrayList<>(4);
        for (StreamMessage m : messages) {
            for (BusSubscription s : route(m.key())) {
                if (s.buffer(m) && !due.contains(s)) { // identity: subscriptions do not define equals
                    due.add(s);
                }
            }
        }
        for (BusSubscription s : due) {
            s.schedule();
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

    /** The slow path of a publish: a key without a cached route (new, or its route table was replaced). */
    private BusSubscription[] learn(StreamKey key, ConcurrentHashMap<StreamKey, BusSubscription[]> table) {
        BusSubscription[] route = routeFor(key);
        boolean isNew;
        synchronized (streamLock) {
            isNew = known.putIfAbsent(key, Boolean.TRUE) == null;
            if (isNew) {
                byAddress.computeIfAbsent(key.source(), a -> new HashSet<>()).add(key);
                byAddress.computeIfAbsent(key.destination(), a -> new HashSet<>()).add(key);
            }
            BusSubscription @Nullable [] cached = table.putIfAbsent(key, route);
            if (cached != null) {
                route = cached;
            }
        }
        if (isNew) {
            announce(key);
        }
        return route;
    }

    /**
     * Forgets every stream whose source or destination is {@code address} — e.g. when the connection
     * of the robot program at {@code "127.0.0.1:40312"} has closed — so that a bus living for days
     * with short-lived connections does not grow with each one. Released streams leave
     * {@link #streams()} and the route cache, and listeners forget they were told about them.
     *
     * <p>
     * Subscribers keep what they have: a message of a released stream still buffered in a subscription
     * is delivered as usual, and whatever a consumer (a view) kept of it is its own. Each subscription
     * matching some of the streams is told through {@link StreamConsumer#released}, after the messages
     * offered to it before the release (so a forwarder can release them on its own bus in order), and
     * release listeners ({@link #onRelease}) are told too. A later message with a released key simply starts the
     * stream again (it is announced as new). Call it after the last publish of those streams; a publish
     * racing with the release may re-create its stream, nothing worse.
     *
     * @return how many streams were released (0 if none had that address)
     */
    public int release(String address) {
        Objects.requireNonNull(address, "address");
        List<StreamKey> gone = new ArrayList<>();
        synchronized (streamLock) {
            @Nullable Set<StreamKey> keys = byAddress.remove(address);
            if (keys != null) {
                for (StreamKey k : keys) {
                    known.remove(k);
                    String other = address.equals(k.source()) ? k.destination() : k.source();
                    @Nullable Set<StreamKey> ofOther = byAddress.get(other);
                    if (ofOther != null && ofOther.remove(k) && ofOther.isEmpty()) {
                        byAddress.remove(other);
                    }
                    gone.add(k);
                }
                ConcurrentHashMap<StreamKey, BusSubscription[]> table = routes;
                for (StreamKey k : gone) {
                    table.remove(k);
                }
            }
        }
        if (gone.isEmpty()) {
            return 0;
        }
        for (StreamListener l : listeners) {
            for (StreamKey k : gone) {
                l.told.remove(k);
            }
        }
        released.add(gone.size());
        Set<StreamKey> told = Set.copyOf(gone);
        for (BusSubscription s : subscriptions) {
            s.offerRelease(address, told);
        }
        for (ReleaseListener l : releaseListeners) {
            tellReleased(l, address, told);
        }
        return gone.size();
    }

    /**
     * Tells {@code listener}, through the delivery executor, the address and the streams of every
     * {@link #release(String)} that released at least one stream after this call.
     */
    public Registration onRelease(BiConsumer<String, Set<StreamKey>> listener) {
        Objects.requireNonNull(listener, "listener");
        ReleaseListener l = new ReleaseListener(listener);
        releaseListeners.add(l);
        return () -> {
            l.closed = true;
            releaseListeners.remove(l);
        };
    }

    private void tellReleased(ReleaseListener l, String address, Set<StreamKey> keys) {
        if (l.closed || closed) {
            return;
        }
        try {
            executor.execute(() -> {
                if (l.closed || closed) {
                    return;
                }
                try {
                    l.listener.accept(address, keys);
                } catch (Throwable t) {
                    listenerFailures.increment();
                }
            });
        } catch (RuntimeException rejected) {
            listenerFailures.increment();
        }
    }

    /** Streams released so far by {@link #release(String)}. */
    public long released() {
        return released.sum();
    }

    /**
     * The bus's own bookkeeping, for tests and benchmarks: known streams, cached routes, addresses
     * indexed, and keys remembered by new-stream listeners (which must all return to their baseline
     * when the streams of closed connections are released).
     */
    public Footprint footprint() {
        int told = 0;
        for (StreamListener l : listeners) {
            told += l.told.size();
        }
        synchronized (streamLock) {
            return new Footprint(known.size(), routes.size(), byAddress.size(), told);
        }
    }

    /** See {@link #footprint()}. */
    public record Footprint(int streams, int routes, int addresses, int listenerKeys) {
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
        for (ReleaseListener l : releaseListeners) {
            l.closed = true;
        }
        releaseListeners.clear();
        if (owned != null) {
            owned.shutdownNow();
        }
    }

    private static final class ReleaseListener {
        final BiConsumer<String, Set<StreamKey>> listener;
        volatile boolean closed;

        ReleaseListener(BiConsumer<String, Set<StreamKey>> listener) {
            this.listener = listener;
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
