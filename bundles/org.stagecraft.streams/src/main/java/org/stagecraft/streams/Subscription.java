package org.stagecraft.streams;

import org.eclipse.jdt.annotation.Nullable;

/**
 * A consumer's subscription to every stream matching a pattern, existing or future. Counters are
 * cumulative and may be read from any thread.
 */
public interface Subscription extends AutoCloseable {
    StreamPattern pattern();

    DeliveryPolicy policy();

    /** Messages handed to the consumer (including those for which it threw). */
    long delivered();

    /**
     * Messages never handed to the consumer: superseded (latest-value), beyond capacity (lossless), or
     * still buffered when the subscription closed.
     */
    long dropped();

    /** Exceptions the consumer threw; delivery continued after each. */
    long failures();

    /** The last exception the consumer threw, or {@code null}. */
    default @Nullable Throwable lastFailure() {
        return null;
    }

    /** Whether {@link #close()} was called (or the bus closed). */
    default boolean isClosed() {
        return false;
    }

    /**
     * Stops delivery: no delivery starts after this returns (one already running on another thread may
     * finish). Undelivered messages are discarded and counted as dropped. Idempotent.
     */
    @Override
    void close();
}
