package org.stagecraft.spy.proxy;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * Records what the spy observes into an MCAP spy log, on a thread of its own ("spy-log"):
 * the observation thread only hands the entries over, so encoding, zstd and the file's CRCs and
 * writes run beside publishing instead of after it (they were more than half of the observation
 * thread's time).
 *
 * <p>Order: entries are written in exactly the order of the calls (one producer, the observation
 * thread; one consumer), so each stream's entries stay in stream order and {@link SpyLogWriter}
 * keeps log times non-decreasing as before.
 *
 * <p>Hand-over: calls are gathered in batches of up to {@value #BATCH_ENTRIES} entries or
 * {@value #BATCH_BYTES} bytes, handed over when full and at every {@link #flush()} (every few tens
 * of milliseconds while there is traffic) and {@link #close()}; the flush has the log thread write
 * the open chunk, so what was handed over is in the file then. Memory: batches waiting for the log thread hold at most
 * {@value #MAX_QUEUED_BYTES} bytes of entries (one larger message is always taken); past that the
 * observation thread waits, so its own queue fills and the forwarding threads wait for room while it
 * makes progress, or, once it has made none for the pipeline's wait limit (a hung disk), count what
 * they cannot queue as unobserved ({@link ObservationPipeline#observationWait}).
 *
 * <p>Failures: the first failure of the log (a full disk: an IOException; or a bug) stops the log
 * thread's writing; the writer is closed, which keeps every complete chunk; the next call (or
 * {@link #close()}) throws it as an IOException saying why, and the observation pipeline reports
 * the log as stopped. Entries handed over after the failure are discarded.
 */
public final class LogRecorder implements SpyRecorder {
    static final int BATCH_ENTRIES = 512;
    static final int BATCH_BYTES = 256 << 10;
    static final long MAX_QUEUED_BYTES = 4L << 20;
    /** The file is forced to the disk at a flush at most this often. */
    static final long FORCE_INTERVAL_MILLIS = 1000;
    /** What an entry other than wire bytes costs in the budget (an estimate: they are small). */
    private static final int SMALL_ENTRY = 128;

    @FunctionalInterface
    private interface Entry {
        void writeTo(SpyLogWriter w) throws IOException;
    }

    private record Batch(List<Entry> entries, long bytes, boolean last) {
    }

    private final SpyLogWriter writer;
    private final Thread thread;

    // the hand-over, guarded by lock
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition notEmpty = lock.newCondition();
    private final Condition notFull = lock.newCondition();
    private final ArrayDeque<Batch> handed = new ArrayDeque<>();
    private long handedBytes;

    // the caller's side (the observation thread)
    private List<Entry> pending = new ArrayList<>(BATCH_ENTRIES);
    private long pendingBytes;
    private boolean closed;

    /** The first failure of the log, or null. */
    private volatile @Nullable Throwable failure;
    /** A force to the disk is running ({@link #forceAside()}). */
    private final AtomicBoolean forcing = new AtomicBoolean();
    /** A failed force, for the log thread to act on (it alone closes the writer). */
    private volatile @Nullable Throwable forceFailure;
    /** When the log thread last had the file forced (the first flush forces it). */
    private long lastForceNanos = System.nanoTime() - TimeUnit.MILLISECONDS.toNanos(FORCE_INTERVAL_MILLIS);

    public LogRecorder(SpyLogWriter writer) {
        this.writer = writer;
        this.thread = Thread.ofPlatform().daemon().name("spy-log").start(this::work);
    }

    public SpyLogWriter writer() {
        return writer;
    }

    /** The wire messages in the file's complete chunks: what a reader gets back, also after a crash or a full disk. */
    @Override
    public Logged logged() {
        return new Logged(writer.messagesLogged(), writer.wireBytesLogged());
    }

    @Override
    public void opened(ConnectionInfo c, long timeNanos) throws IOException {
        add(w -> w.connectionOpened(timeNanos, c.id(), c.client(), c.listen(), c.upstream()), SMALL_ENTRY);
    }

    @Override
    public void closed(ConnectionInfo c, long timeNanos, String reason) throws IOException {
        add(w -> w.connectionClosed(timeNanos, c.id(), reason), SMALL_ENTRY);
    }

    @Override
    public void wire(ConnectionInfo c, Direction dir, WireEvent event, long timeNanos) throws IOException {
        add(w -> w.wire(timeNanos, c.id(), c.port(), dir, event), SMALL_ENTRY + size(event));
    }

    @Override
    public void diagnostic(ConnectionInfo c, Direction dir, long streamOffset, String text, long timeNanos)
            throws IOException {
        add(w -> w.diagnostic(timeNanos, c.id(), dir, streamOffset, text), SMALL_ENTRY + 2L * text.length());
    }

    @Override
    public void hold(HoldEntry entry) throws IOException {
        add(w -> w.hold(entry), SMALL_ENTRY + entry.length());
    }

    /**
     * Hands everything so far to the log thread, which writes the open chunk (so a killed process
     * loses nothing before it) and, when the last force is {@value #FORCE_INTERVAL_MILLIS} ms old or
     * more, has the file forced to the disk beside it ({@link #forceAside()}): the observation pipeline
     * flushes every few tens of milliseconds while there is traffic (the crash window), and an fsync
     * that often would cost the disk, not the process, what it saves.
     */
    @Override
    public void flush() throws IOException {
        add(w -> {
            w.flush();
            long now = System.nanoTime();
            if (now - lastForceNanos >= TimeUnit.MILLISECONDS.toNanos(FORCE_INTERVAL_MILLIS)) {
                lastForceNanos = now;
                forceAside();
            }
        }, 0);
        handOver(false);
    }

    /**
     * Forces the file to the disk on a thread of its own ("spy-log-sync"), unless a force is still
     * running: an fsync can take hundreds of milliseconds on a busy disk, and the log thread waiting
     * for it held up observation and so, with complete observation, the wire (issue 17).
     */
    private void forceAside() {
        if (!forcing.compareAndSet(false, true)) {
            return;
        }
        Thread.ofPlatform().daemon().name("spy-log-sync").start(() -> {
            try {
                writer.force();
            } catch (Throwable t) {
                forceFailure = t;
            } finally {
                forcing.set(false);
            }
        });
    }

    /** Hands the rest over, waits until the log thread has written it and closed the file. */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        handOver(true);
        try {
            thread.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while the spy log was being finished", e);
        }
        check();
    }

    // ---- the caller's side ---------------------------------------------------------------------

    private void add(Entry e, long bytes) throws IOException {
        check();
        if (closed) {
            throw new IOException("the spy log is closed");
        }
        pending.add(e);
        pendingBytes += bytes;
        if (pending.size() >= BATCH_ENTRIES || pendingBytes >= BATCH_BYTES) {
            handOver(false);
        }
    }

    private void check() throws IOException {
        Throwable f = failure;
        if (f != null) {
            throw f instanceof IOException io ? new IOException(io.getMessage(), io)
                    : new IOException(ObservationPipeline.describe(f), f);
        }
    }

    /** Queues the pending batch; waits while the log thread is {@link #MAX_QUEUED_BYTES} behind. */
    private void handOver(boolean last) throws IOException {
        if (pending.isEmpty() && !last) {
            return;
        }
        Batch b = new Batch(pending, pendingBytes, last);
        pending = new ArrayList<>(BATCH_ENTRIES);
        pendingBytes = 0;
        lock.lock();
        try {
            while (!handed.isEmpty() && handedBytes + b.bytes() > MAX_QUEUED_BYTES && failure == null) {
                notFull.awaitUninterruptibly();
            }
            handed.add(b);
            handedBytes += b.bytes();
            notEmpty.signal();
        } finally {
            lock.unlock();
        }
    }

    private static long size(WireEvent e) {
        return switch (e) {
            case WireEvent.Frame f -> f.wireSize();
            case WireEvent.Unframed u -> u.length();
            case WireEvent.Banner b -> MessageHeader.SIZE;
        };
    }

    // ---- the log thread ------------------------------------------------------------------------

    private void work() {
        while (true) {
            Batch b;
            lock.lock();
            try {
                while (handed.isEmpty()) {
                    notEmpty.awaitUninterruptibly();
                }
                b = handed.peek();
            } finally {
                lock.unlock();
            }
            Throwable forced = forceFailure;
            if (forced != null && failure == null) {
                fail(forced);
            }
            if (failure == null) {
                for (Entry e : b.entries()) {
                    try {
                        e.writeTo(writer);
                    } catch (Throwable t) {
                        fail(t);
                        break;
                    }
                }
            }
            lock.lock();
            try {
                handed.poll();
                handedBytes -= b.bytes();
                notFull.signalAll();
            } finally {
                lock.unlock();
            }
            if (b.last()) {
                if (failure == null) {
                    try {
                        writer.close();
                    } catch (Throwable t) {
                        fail(t);
                    }
                }
                return;
            }
        }
    }

    /** Stops writing: the writer is closed (keeping its complete chunks) and the failure kept for the caller. */
    private void fail(Throwable t) {
        try {
            writer.close();
        } catch (Throwable ignored) {
            // already failing; the first error is the one reported
        }
        failure = t;
        lock.lock();
        try {
            notFull.signalAll();
        } finally {
            lock.unlock();
        }
    }
}
