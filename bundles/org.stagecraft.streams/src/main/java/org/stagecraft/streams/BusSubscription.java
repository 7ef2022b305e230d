package org.stagecraft.streams;

import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;

import org.eclipse.jdt.annotation.Nullable;

/**
 * A subscription with its buffer and its drain task. Publishers call {@link #offer} (or, for many
 * messages at once, {@link #buffer} for each and {@link #schedule} once), lock-free and
 * bounded; at most one drain task runs (or is queued on the executor) at a time.
 */
final class BusSubscription implements Subscription {
    private final StreamBus bus;
    private final StreamPattern pattern;
    private final DeliveryPolicy policy;
    private final StreamConsumer consumer;
    private final boolean lossless;
    private final int capacity;
    /** Whether the consumer does anything with releases: a lambda (most views) cannot, and is never queued any. */
    private final boolean wantsReleases;

    /** Lossless: FIFO with an explicit size, never more than {@code capacity} messages. */
    private final @Nullable ConcurrentLinkedQueue<StreamMessage> fifo;
    private final AtomicInteger size = new AtomicInteger();
    /** Latest-value: the newest undelivered message per stream. */
    private final @Nullable ConcurrentHashMap<StreamKey, StreamMessage> latest;
    /** Latest-value: releases, told after the pending messages (a lossless FIFO carries them in line). */
    private final @Nullable ConcurrentLinkedQueue<Release> releases;

    /** A release in the buffer: never counted against the capacity, nor as delivered or dropped. */
    private record Release(String address, Set<StreamKey> streams) {
    }

    private final AtomicBoolean scheduled = new AtomicBoolean();
    private final LongAdder delivered = new LongAdder();
    private final LongAdder dropped = new LongAdder();
    private final LongAdder failures = new LongAdder();
    private volatile @Nullable Throwable lastFailure;
    private volatile boolean closed;

    BusSubscription(StreamBus bus, StreamPattern pattern, DeliveryPolicy policy, StreamConsumer consumer) {
        this.bus = bus;
        this.pattern = pattern;
        this.policy = policy;
        this.consumer = consumer;
        this.lossless = policy.isLossless();
        this.capacity = policy.capacity();
        this.wantsReleases = overridesReleased(consumer);
        this.fifo = lossless ? new ConcurrentLinkedQueue<>() : null;
        this.latest = lossless ? null : new ConcurrentHashMap<>();
        this.releases = lossless ? null : new ConcurrentLinkedQueue<>();
    }

    /** Called by publishers: buffer (or drop and count) and make sure a drain task is pending. */
    void offer(StreamMessage m) {
        if (buffer(m)) {
            schedule();
        }
    }

    /**
     * Buffers {@code m} (or drops and counts it) without scheduling the drain task; the caller must
     * {@link #schedule()} afterwards when this returns true ({@link StreamBus#publishAll}).
     */
    boolean buffer(StreamMessage m) {
        if (closed) {
            return false;
        }
        if (lossless) {
            if (size.incrementAndGet() > capacity) {
                size.decrementAndGet();
                dropped.increment();
                return false;
            }
            fifo.offer(m);
        } else if (latest.put(m.key(), m) != null) {
            dropped.increment(); // superseded before delivery
        }
        return true;
    }

    /** Called by {@link StreamBus#release}: buffers the release behind the messages offered before it. */
    void offerRelease(String address, Set<StreamKey> released) {
        if (closed || !wantsReleases) {
            return;
        }
        Set<StreamKey> mine = new HashSet<>();
        for (StreamKey k : released) {
            if (pattern.matches(k)) {
                mine.add(k);
            }
        }
        if (mine.isEmpty()) {
            return;
        }
        Release r = new Release(address, Set.copyOf(mine));
        if (lossless) {
            size.incrementAndGet();
            fifo.offer(new StreamMessage(mine.iterator().next(), 0, r));
        } else {
            releases.offer(r);
        }
        schedule();
    }

    private static boolean overridesReleased(StreamConsumer consumer) {
        try {
            return consumer.getClass().getMethod("released", String.class, Set.class).getDeclaringClass() != StreamConsumer.class;
        } catch (NoSuchMethodException | SecurityException e) {
            return true; // cannot tell: tell it
        }
    }

    /** Releases waiting for a latest-value consumer (for tests: they are only queued for consumers that want them). */
    int pendingReleases() {
        return lossless ? 0 : releases.size();
    }

    /** Makes sure a drain task is pending. */
    void schedule() {
        if (scheduled.compareAndSet(false, true)) {
            submit();
        }
    }

    private void submit() {
        try {
            bus.executor().execute(this::drain);
        } catch (RuntimeException rejected) { // executor shut down (bus closed) or display disposed
            scheduled.set(false);
            if (!closed) {
                failures.increment();
                lastFailure = rejected;
            }
        }
    }

    private void drain() {
        int budget = StreamBus.BATCH;
        for (;;) {
            budget -= lossless ? drainFifo(budget) : drainLatest();
            if (closed) {
                scheduled.set(false);
                discard();
                return;
            }
            if (budget <= 0 && !isEmpty()) {
                submit(); // still scheduled: let other tasks of the executor run first
                return;
            }
            scheduled.set(false);
            // a publisher may have offered after the last poll but seen scheduled == true
            if (isEmpty() || !scheduled.compareAndSet(false, true)) {
                return;
            }
        }
    }

    private int drainFifo(int budget) {
        int n = 0;
        StreamMessage m;
        while (n < budget && !closed && (m = fifo.poll()) != null) {
            size.decrementAndGet();
            if (m.payload() instanceof Release r) {
                tellReleased(r);
            } else {
                deliver(m);
            }
            n++;
        }
        return n;
    }

    /** One pass: the newest message of each stream that has one. */
    private int drainLatest() {
        int n = 0;
        for (StreamKey k : latest.keySet()) {
            if (closed) {
                break;
            }
            @Nullable StreamMessage m = latest.remove(k);
            if (m != null) {
                deliver(m);
                n++;
            }
        }
        for (Release r = releases.poll(); r != null && !closed; r = releases.poll()) {
            tellReleased(r);
            n++;
        }
        return n;
    }

    private void tellReleased(Release r) {
        try {
            consumer.released(r.address(), r.streams());
        } catch (Throwable t) {
            failures.increment();
            lastFailure = t;
        }
    }

    private void deliver(StreamMessage m) {
        try {
            consumer.accept(m);
        } catch (Throwable t) {
            failures.increment();
            lastFailure = t;
        } finally {
            delivered.increment();
        }
    }

    /** Messages buffered now (for tests: the memory bound). */
    int pending() {
        return lossless ? size.get() : latest.size();
    }

    private boolean isEmpty() {
        return lossless ? fifo.isEmpty() : latest.isEmpty() && releases.isEmpty();
    }

    private void discard() {
        if (lossless) {
            for (StreamMessage m = fifo.poll(); m != null; m = fifo.poll()) {
                size.decrementAndGet();
                if (!(m.payload() instanceof Release)) {
                    dropped.increment();
                }
            }
        } else {
            releases.clear();
            for (StreamKey k : latest.keySet()) {
                if (latest.remove(k) != null) {
                    dropped.increment();
                }
            }
        }
    }

    @Override
    public StreamPattern pattern() {
        return pattern;
    }

    @Override
    public DeliveryPolicy policy() {
        return policy;
    }

    @Override
    public long delivered() {
        return delivered.sum();
    }

    @Override
    public long dropped() {
        return dropped.sum();
    }

    @Override
    public long failures() {
        return failures.sum();
    }

    @Override
    public @Nullable Throwable lastFailure() {
        return lastFailure;
    }

    @Override
    public boolean isClosed() {
        return closed;
    }

    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        bus.unsubscribe(this);
        discard();
    }

    @Override
    public String toString() {
        return "Subscription[" + pattern + ", " + policy + ", delivered=" + delivered() + ", dropped=" + dropped()
                + ", failures=" + failures() + (closed ? ", closed" : "") + "]";
    }
}
