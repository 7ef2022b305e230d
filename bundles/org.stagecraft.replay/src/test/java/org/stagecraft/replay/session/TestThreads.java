package org.stagecraft.replay.session;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;

/**
 * A session's threads in a plain test: background work on daemon threads, the owner is the test's own
 * thread, which runs what was handed to it while it waits for a condition ({@link #runUntil}), as the
 * UI thread's event loop would.
 */
final class TestThreads implements SessionThreads, AutoCloseable {
    private final ExecutorService pool = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "replay session test work");
        t.setDaemon(true);
        return t;
    });
    private final LinkedBlockingQueue<Runnable> owner = new LinkedBlockingQueue<>();
    private volatile boolean ownerGone;
    final AtomicInteger started = new AtomicInteger();
    final AtomicInteger cancelled = new AtomicInteger();

    @Override
    public Work background(String name, boolean quiet, Task task) {
        started.incrementAndGet();
        AtomicBoolean cancel = new AtomicBoolean();
        pool.execute(() -> task.run(new Progress() {
            @Override
            public boolean cancelled() {
                return cancel.get();
            }

            @Override
            public void done(double fraction) {
            }
        }));
        return () -> {
            cancelled.incrementAndGet();
            cancel.set(true);
        };
    }

    @Override
    public void onOwner(Runnable r) {
        if (ownerGone) {
            throw new RejectedExecutionException("the owner is gone");
        }
        owner.add(r);
    }

    /** The owner goes away (the workbench closes): nothing more is handed to it. */
    void ownerGone() {
        ownerGone = true;
    }

    /** Runs what is handed to the owner until {@code condition} holds; fails after {@code timeoutMillis}. */
    void runUntil(BooleanSupplier condition, long timeoutMillis, String what) throws InterruptedException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (!condition.getAsBoolean()) {
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                throw new AssertionError("timed out after " + timeoutMillis + " ms waiting for " + what);
            }
            // wakes up for each task handed over, and at least every 10 ms: background work changes conditions too
            Runnable r = owner.poll(Math.min(left, 10_000_000L), TimeUnit.NANOSECONDS);
            if (r != null) {
                r.run();
            }
        }
    }

    @Override
    public void close() {
        pool.shutdownNow();
    }
}
