package org.stagecraft.streams;

import org.eclipse.jdt.annotation.Nullable;

/**
 * How a subscription's messages are buffered between the publisher and the consumer. Neither policy
 * ever blocks the publisher.
 * <ul>
 * <li>{@link #latestValue()}: per stream only the newest undelivered message is kept; when the consumer
 * is ready it gets the newest message of each stream, superseded ones count as dropped. Memory is one
 * message per matching stream. For visualisations.</li>
 * <li>{@link #lossless(int)}: a FIFO of at most {@code capacity} messages; messages arriving while it is
 * full are dropped and counted. For loggers, with a capacity sized to ride out their hiccups.</li>
 * </ul>
 */
public final class DeliveryPolicy {

    /** The two kinds of policy. */
    public enum Kind {
        LATEST_VALUE, LOSSLESS
    }

    private static final DeliveryPolicy LATEST = new DeliveryPolicy(Kind.LATEST_VALUE, 0);

    private final Kind kind;
    private final int capacity;

    private DeliveryPolicy(Kind kind, int capacity) {
        this.kind = kind;
        this.capacity = capacity;
    }

    /** Keep only the newest undelivered message per stream. */
    public static DeliveryPolicy latestValue() {
        return LATEST;
    }

    /** Deliver every message in order, buffering at most {@code capacity} (at least 1); overflow is dropped and counted. */
    public static DeliveryPolicy lossless(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("lossless capacity must be at least 1, not " + capacity);
        }
        return new DeliveryPolicy(Kind.LOSSLESS, capacity);
    }

    public Kind kind() {
        return kind;
    }

    public boolean isLossless() {
        return kind == Kind.LOSSLESS;
    }

    /** The buffer capacity of a lossless policy; 0 for latest-value. */
    public int capacity() {
        return capacity;
    }

    @Override
    public boolean equals(@Nullable Object o) {
        return o instanceof DeliveryPolicy p && p.kind == kind && p.capacity == capacity;
    }

    @Override
    public int hashCode() {
        return kind.hashCode() * 31 + capacity;
    }

    @Override
    public String toString() {
        return kind == Kind.LATEST_VALUE ? "latest-value" : "lossless(" + capacity + ")";
    }
}
