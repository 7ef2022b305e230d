package org.stagecraft.spy.proxy;

import java.time.Instant;

/** Receive timestamps: epoch nanoseconds, monotonic within a run (wall time at start + nanoTime). */
public final class WallClock {
    private static final long START_EPOCH_NANOS;
    private static final long START_NANO_TIME;

    static {
        Instant now = Instant.now();
        START_NANO_TIME = System.nanoTime();
        START_EPOCH_NANOS = now.getEpochSecond() * 1_000_000_000L + now.getNano();
    }

    private WallClock() {
    }

    public static long nowNanos() {
        return START_EPOCH_NANOS + (System.nanoTime() - START_NANO_TIME);
    }
}
