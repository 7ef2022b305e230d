package org.stagecraft.replay.play;

/**
 * The time source a {@link Replayer} paces itself by. Tests give one that records the waits
 * instead of sleeping, so timing is checked exactly and fast.
 */
public interface ReplayClock {

    long nanoTime();

    /** Waits until {@link #nanoTime()} reaches {@code deadlineNanos}. */
    void sleepUntil(long deadlineNanos) throws InterruptedException;

    /** The system's monotonic clock. */
    static ReplayClock system() {
        return SystemReplayClock.INSTANCE;
    }
}
