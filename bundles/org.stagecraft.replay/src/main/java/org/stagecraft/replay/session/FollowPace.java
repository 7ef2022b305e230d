package org.stagecraft.replay.session;

/**
 * How long to wait before looking at a growing log again: reading it again costs a reopen (a spy log
 * without its summary is scanned whole) and a timeline pass over all of it, both growing with the
 * session. Waiting a multiple of what the last look cost keeps a long live session to a bounded share
 * of the CPU (at most about 1 / (1 + factor)), never less than a floor so a short log stays lively.
 */
public final class FollowPace {
    private final int minMillis;
    private final int factor;
    private volatile long reopenNanos;
    private volatile long timelineNanos;

    public FollowPace(int minMillis, int factor) {
        this.minMillis = minMillis;
        this.factor = factor;
    }

    /** The last (re)open took this long. */
    public void reopened(long nanos) {
        reopenNanos = nanos;
    }

    /** The last timeline pass took this long (any thread). */
    public void timelinePassed(long nanos) {
        timelineNanos = nanos;
    }

    /** The floor: how often a cheap log is looked at. */
    public int minMillis() {
        return minMillis;
    }

    /** The least time between the start of one look and the start of the next. */
    public long delayMillis() {
        return Math.max(minMillis, factor * ((reopenNanos + timelineNanos) / 1_000_000));
    }
}
