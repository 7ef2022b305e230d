package org.stagecraft.pydev.tests;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.IDebugEventSetListener;

/** Records the debug events the platform fires and lets a test wait for one (no polling, no sleeps). */
final class DebugEvents implements IDebugEventSetListener, AutoCloseable {
    private final List<DebugEvent> seen = new ArrayList<>();
    /** When each event reached this listener: System.nanoTime() and the wall clock in epoch nanoseconds. */
    private final java.util.Map<DebugEvent, long[]> arrivals = new java.util.IdentityHashMap<>();

    DebugEvents() {
        DebugPlugin.getDefault().addDebugEventListener(this);
    }

    @Override
    public synchronized void handleDebugEvents(DebugEvent[] events) {
        long nano = System.nanoTime();
        java.time.Instant now = java.time.Instant.now();
        for (DebugEvent e : events) {
            arrivals.put(e, new long[] {nano, now.getEpochSecond() * 1_000_000_000L + now.getNano()});
        }
        seen.addAll(List.of(events));
        notifyAll();
    }

    /** The first event (seen so far or to come) that matches, or an AssertionError after {@code timeout}. */
    synchronized DebugEvent await(String what, Duration timeout, Predicate<DebugEvent> matches) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        int checked = 0;
        while (true) {
            for (; checked < seen.size(); checked++) {
                if (matches.test(seen.get(checked))) {
                    return seen.get(checked);
                }
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                throw new AssertionError("timed out after " + timeout + " waiting for " + what + "; events seen: " + seen + Threads.dump());
            }
            TimeUnit.NANOSECONDS.timedWait(this, left);
        }
    }

    /** When {@code e} arrived here: {System.nanoTime(), epoch nanoseconds}. */
    synchronized long[] arrival(DebugEvent e) {
        return arrivals.get(e).clone();
    }

    @Override
    public void close() {
        DebugPlugin.getDefault().removeDebugEventListener(this);
    }
}
