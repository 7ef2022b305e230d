package org.stagecraft.recording.play;

import java.util.concurrent.locks.LockSupport;

/**
 * Brings a replay to the moments of the recording: an offset of {@code s} recorded seconds is due
 * {@code s / speed} seconds after the start. Deadlines are absolute, so time spent writing one chunk
 * is not added to the wait for the next one and a long replay does not drift.
 */
final class Pacer {
    private final long startNanos;
    private final double speed;

    Pacer(double speed) {
        if (!(speed > 0) || Double.isInfinite(speed)) {
            throw new IllegalArgumentException("replay speed must be a positive number, not " + speed);
        }
        this.startNanos = System.nanoTime();
        this.speed = speed;
    }

    void awaitOffset(double seconds) throws InterruptedException {
        long due = startNanos + (long) (seconds / speed * 1e9);
        for (long left = due - System.nanoTime(); left > 0; left = due - System.nanoTime()) {
            LockSupport.parkNanos(left);
            if (Thread.interrupted()) {
                throw new InterruptedException("replay stopped");
            }
        }
    }
}
