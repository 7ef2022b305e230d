package org.stagecraft.replay.play;

import java.util.ArrayList;
import java.util.List;

/**
 * A clock for tests. In free-running mode a wait ends at once with the time moved to the deadline,
 * so a whole log plays instantly with its timing exact, and {@link #deadlines()} says when each
 * message was due. In gated mode a wait blocks until the test moves the time to the deadline (or
 * the waiter is interrupted).
 */
final class ManualClock implements ReplayClock {
    private final boolean gated;
    private long now;
    private final List<Long> deadlines = new ArrayList<>();
    /** Waits that had to block, and the deadline of the latest. */
    private int blocked;
    private long blockedDeadline;

    ManualClock(boolean gated, long start) {
        this.gated = gated;
        this.now = start;
    }

    @Override
    public synchronized long nanoTime() {
        return now;
    }

    @Override
    public synchronized void sleepUntil(long deadline) throws InterruptedException {
        deadlines.add(deadline);
        if (!gated) {
            now = Math.max(now, deadline);
            return;
        }
        if (now < deadline) {
            blocked++;
            blockedDeadline = deadline;
            notifyAll();
        }
        while (now < deadline) {
            wait();
        }
    }

    synchronized List<Long> deadlines() {
        return List.copyOf(deadlines);
    }

    synchronized void advanceTo(long time) {
        now = Math.max(now, time);
        notifyAll();
    }

    /** Blocks until the {@code n}-th blocking wait has begun (at most 10 s); @return its deadline */
    synchronized long awaitBlocked(int n) throws InterruptedException {
        long end = System.nanoTime() + 10_000_000_000L;
        while (blocked < n) {
            long left = end - System.nanoTime();
            if (left <= 0) {
                throw new AssertionError("the replayer waited " + blocked + " times, expected " + n);
            }
            wait(left / 1_000_000 + 1);
        }
        return blockedDeadline;
    }
}
