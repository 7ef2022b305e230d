package org.stagecraft.replay.play;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;

/**
 * Plays a {@link SessionLog} into a {@link StreamBus}: each message is published as
 * {@link LogMessage#toStreamMessage()} at its recorded time relative to the start of play, scaled
 * by the speed, so views work on replayed data exactly as on live data. Play runs on a thread of
 * its own; every method may be called from any thread.
 *
 * <p>Pacing is anchored: when play starts (and after every seek, step or change of speed) the
 * replayer notes the wall time and the log time, and each message is due at
 * {@code anchorWall + (t - anchorLog) / speed}. Waiting for a deadline rather than for a delay
 * keeps late messages from making every later one late as well.
 */
public final class Replayer implements AutoCloseable {
    public static final double MIN_SPEED = 0.1;
    public static final double MAX_SPEED = 16;

    private final SessionLog log;
    private final StreamBus bus;
    private final ReplayClock clock;
    private final LogCursor cursor;
    private final List<ReplayListener> listeners = new CopyOnWriteArrayList<>();
    private final java.util.concurrent.atomic.AtomicLong listenerFailures = new java.util.concurrent.atomic.AtomicLong();
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition wake = lock.newCondition();
    private final Thread thread;
    private final DeviceReplies deviceReplies;

    // guarded by lock
    private boolean playing;
    private boolean closed;
    private double speed = 1;
    private long position;
    /** Taken from the cursor by the play thread, waiting for its time; not yet published. */
    private @Nullable LogMessage taken;
    /** Changes whenever the position, speed or play state changes, so a waiting message is re-timed. */
    private long generation;
    private long anchorWall;
    private long anchorLog;
    private @Nullable Exception failure;
    /** The message last published, with the cursor right after it; null after a seek. */
    private @Nullable LogMessage lastPublished;

    public Replayer(SessionLog log, StreamBus bus, ReplayClock clock) throws IOException {
        this.log = log;
        this.bus = bus;
        this.clock = clock;
        this.cursor = log.cursor(log.startNanos());
        this.position = log.startNanos();
        this.deviceReplies = new DeviceReplies(log);
        this.thread = Thread.ofPlatform().daemon().name("stagecraft-replay " + log.path().getFileName())
                .unstarted(this::run);
        thread.start();
    }

    /**
     * Every bus message a play of {@code log} from its start to its end publishes, in order, at once:
     * no pacing and no thread (tests and benchmarks that feed a model directly). Memory grows with the
     * log, so this is for small logs.
     */
    public static List<StreamMessage> allPublished(SessionLog log) throws IOException {
        List<StreamMessage> out = new ArrayList<>();
        try (LogCursor all = log.cursor(log.startNanos())) {
            for (LogMessage m = all.next(); m != null; m = all.next()) {
                m.toStreamMessage().ifPresent(out::add);
            }
        }
        return out;
    }

    /** Plays from the current position at the current speed. */
    public void play() {
        lock.lock();
        try {
            checkOpen();
            if (!playing) {
                playing = true;
                changed();
            }
        } finally {
            lock.unlock();
        }
        fireState();
    }

    public void pause() {
        boolean was;
        lock.lock();
        try {
            was = playing;
            pauseLocked();
        } finally {
            lock.unlock();
        }
        if (was) {
            fireState();
        }
    }

    private void pauseLocked() {
        if (playing) {
            playing = false;
            untake();
            changed();
        }
    }

    public boolean playing() {
        lock.lock();
        try {
            return playing;
        } finally {
            lock.unlock();
        }
    }

    /** @throws IllegalArgumentException outside {@link #MIN_SPEED}..{@link #MAX_SPEED} */
    public void setSpeed(double newSpeed) {
        if (!(newSpeed >= MIN_SPEED && newSpeed <= MAX_SPEED)) {
            throw new IllegalArgumentException("replay speed " + newSpeed + " is outside " + MIN_SPEED + ".." + MAX_SPEED);
        }
        lock.lock();
        try {
            checkOpen();
            long at = playing ? reached() : position;
            speed = newSpeed;
            changed(at);
        } finally {
            lock.unlock();
        }
        fireState();
    }

    public double speed() {
        lock.lock();
        try {
            return speed;
        } finally {
            lock.unlock();
        }
    }

    /** Moves the position to {@code timeNanos} (clamped to the log) without publishing. */
    public void seek(long timeNanos) {
        long at = Math.max(log.startNanos(), Math.min(log.endNanos(), timeNanos));
        lock.lock();
        try {
            checkOpen();
            io(() -> cursor.seek(at));
            taken = null;
            lastPublished = null;
            position = at;
            publishDeviceReplies(at);
            changed();
        } finally {
            lock.unlock();
        }
        fireMoved(at, null);
    }

    /** Moves to {@code message} so that it is the next to publish. */
    public void seekTo(LogMessage message) {
        lock.lock();
        try {
            checkOpen();
            io(() -> cursor.seekTo(message)); // may refuse a message of another log: then nothing moved
            taken = null;
            lastPublished = null;
            position = message.timeNanos();
            publishDeviceReplies(message.timeNanos());
            changed();
        } finally {
            lock.unlock();
        }
        fireMoved(message.timeNanos(), null);
    }

    /**
     * Moves just past {@code message}, as if it had been published last: the next message published
     * is the one after it, and a step back shows the one before it. Publishes nothing (e.g. when a
     * log is opened again and replay goes on where it was).
     */
    public void seekAfter(LogMessage message) {
        lock.lock();
        try {
            checkOpen();
            io(() -> {
                cursor.seekTo(message);
                cursor.next();
            });
            taken = null;
            lastPublished = message;
            position = message.timeNanos();
            changed();
        } finally {
            lock.unlock();
        }
        fireMoved(message.timeNanos(), message);
    }

    /** The message last published (the one on show); null after a seek. */
    public @Nullable LogMessage lastPublished() {
        lock.lock();
        try {
            return lastPublished;
        } finally {
            lock.unlock();
        }
    }

    /** Publishes the next message and moves past it; null at the end. Pauses play first. */
    public @Nullable LogMessage stepForward() {
        return step(cursor::next);
    }

    /**
     * Publishes the message before the one on show (or, after a seek, the one before the position)
     * and moves just past it, so a step forward shows again what followed; null at the start, where
     * nothing moves. Pauses play first.
     */
    public @Nullable LogMessage stepBack() {
        return step(() -> {
            boolean onShow = lastPublished != null;
            if (onShow) {
                cursor.previous(); // back before the message on show
            }
            LogMessage before = cursor.previous();
            if (before == null) {
                if (onShow) {
                    cursor.next(); // nothing before it: it stays on show
                }
                return null;
            }
            cursor.next(); // just past it again
            return before;
        });
    }

    private @Nullable LogMessage step(IoCall<@Nullable LogMessage> move) {
        LogMessage m;
        boolean was;
        lock.lock();
        try {
            checkOpen();
            was = playing;
            pauseLocked();
            m = io(move);
            if (m != null) {
                publish(m);
            }
        } finally {
            lock.unlock();
        }
        if (was) {
            fireState();
        }
        if (m != null) {
            fireMoved(m.timeNanos(), m);
        }
        return m;
    }

    /** Log time of the current position. */
    public long position() {
        lock.lock();
        try {
            return position;
        } finally {
            lock.unlock();
        }
    }

    /** The log being played. */
    public SessionLog log() {
        return log;
    }

    /**
     * The error that stopped play (reading the log failed, or a message could not be decoded or
     * published; play pauses then); null if none did.
     */
    public @Nullable Exception failure() {
        lock.lock();
        try {
            return failure;
        } finally {
            lock.unlock();
        }
    }

    public void addListener(ReplayListener listener) {
        listeners.add(listener);
    }

    public void removeListener(ReplayListener listener) {
        listeners.remove(listener);
    }

    /** Stops play; the log stays open (its owner closes it). */
    @Override
    public void close() {
        lock.lock();
        try {
            if (closed) {
                return;
            }
            closed = true;
            playing = false;
            changed();
        } finally {
            lock.unlock();
        }
        try {
            thread.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        deviceReplies.close();
        try {
            cursor.close();
        } catch (IOException e) {
            // nothing is held but buffers; the log's owner closes the file
        }
    }

    // --- the play thread -------------------------------------------------------------------------

    private void run() {
        while (true) {
            LogMessage m;
            long due = 0;
            long gen;
            lock.lock();
            try {
                while (!playing && !closed) {
                    wake.awaitUninterruptibly();
                }
                // Interrupts only wake a sleeping wait; the flag must not reach the cursor's file
                // channel, which an interrupt would close for good.
                Thread.interrupted();
                if (closed) {
                    return;
                }
                m = taken; // a message still waiting after a change of speed is timed again
                if (m == null) {
                    try {
                        m = cursor.next();
                    } catch (IOException e) {
                        failure = e;
                    } catch (UncheckedIOException e) {
                        failure = e.getCause();
                    } catch (RuntimeException e) {
                        failure = e; // a bug in a decoder or the log: play stops and says so
                    }
                }
                if (m == null) {
                    playing = false;
                    changed();
                } else {
                    taken = m;
                    due = anchorWall + (long) ((m.timeNanos() - anchorLog) / speed);
                }
                gen = generation;
            } finally {
                lock.unlock();
            }
            if (m == null) {
                fireState();
                continue;
            }
            try {
                clock.sleepUntil(due);
            } catch (InterruptedException e) {
                // woken by a change (pause, seek, speed, close): decided below under the lock
            }
            boolean published = false;
            boolean failed = false;
            lock.lock();
            try {
                if (generation == gen && taken == m && playing) {
                    taken = null;
                    publish(m);
                    published = true;
                }
            } catch (RuntimeException e) {
                failure = e; // e.g. the bus was closed under us: stop, do not die silently
                playing = false;
                changed();
                failed = true;
            } finally {
                lock.unlock();
            }
            if (failed) {
                fireState();
                continue;
            }
            if (published) {
                fireMoved(m.timeNanos(), m);
            }
        }
    }

    /** Puts a message the play thread took but did not publish back, so the cursor is at the position. */
    private void untake() {
        if (taken != null) {
            taken = null;
            io(cursor::previous);
        }
    }

    /**
     * After a jump, what a live view would know by then: the latest geometry and configuration
     * replies of each device before the new position (see {@link DeviceReplies}).
     */
    private void publishDeviceReplies(long before) {
        for (LogMessage m : deviceReplies.before(before)) {
            m.toStreamMessage().ifPresent(bus::publish);
        }
    }

    /** For tests: waits until the pass that finds device replies has read the log. */
    boolean awaitDeviceReplies(long millis) throws InterruptedException {
        return deviceReplies.awaitDone(millis);
    }

    private void publish(LogMessage m) {
        position = m.timeNanos();
        lastPublished = m;
        m.toStreamMessage().ifPresent(bus::publish);
    }

    /**
     * Re-anchors the pacing at the current position and wakes the play thread; call with the lock,
     * after the change.
     */
    private void changed() {
        changed(position);
    }

    /** As {@link #changed()}, anchoring the pacing at log time {@code anchorAt}. */
    private void changed(long anchorAt) {
        generation++;
        anchorWall = clock.nanoTime();
        anchorLog = anchorAt;
        wake.signalAll();
        if (Thread.currentThread() != thread) {
            thread.interrupt();
        }
    }

    /**
     * The log time play has reached: past the last message published when the log is quiet, so a
     * change of speed in a quiet stretch does not restart the wait. Call with the lock, while playing.
     */
    private long reached() {
        return Math.max(position, anchorLog + (long) ((clock.nanoTime() - anchorWall) * speed));
    }

    private interface IoCall<T> {
        T call() throws IOException;
    }

    private interface IoRun {
        void run() throws IOException;
    }

    private static <T> T io(IoCall<T> call) {
        try {
            return call.call();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static void io(IoRun run) {
        try {
            run.run();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("replayer closed");
        }
    }

    private void fireMoved(long time, @Nullable LogMessage last) {
        for (ReplayListener l : listeners) {
            try {
                l.moved(time, last);
            } catch (RuntimeException e) {
                listenerFailures.incrementAndGet(); // a broken listener must not stop play
            }
        }
    }

    /** How often a listener threw (each call is isolated, play goes on). */
    public long listenerFailures() {
        return listenerFailures.get();
    }

    private void fireState() {
        boolean p;
        double s;
        lock.lock();
        try {
            p = playing;
            s = speed;
        } finally {
            lock.unlock();
        }
        for (ReplayListener l : listeners) {
            try {
                l.stateChanged(p, s);
            } catch (RuntimeException e) {
                listenerFailures.incrementAndGet();
            }
        }
    }
}
