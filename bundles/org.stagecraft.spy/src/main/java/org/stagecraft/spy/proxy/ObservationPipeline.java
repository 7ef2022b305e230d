package org.stagecraft.spy.proxy;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.HoldStreams;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;

/**
 * Turns what the spy forwarded into messages, in two stages.
 *
 * <p><b>On the forwarding thread</b>, after the bytes went out: each connection direction has its
 * own {@link PlayerFramer}, fed straight from the relay's buffer (no copy of the chunk); complete
 * messages are decoded there too, so connections are framed and decoded in parallel. The events
 * are queued for the second stage. The queue is bounded by bytes, with a fair share per
 * connection once it is half full, so one connection (say, one sending garbage) cannot take the
 * others' room: what is refused is dropped from observation (never from the wire), counted, and
 * reported as a gap at its exact offset; framing stays aligned.
 *
 * <p><b>On the observation thread</b>: publishing on the stream bus and recording to the spy log,
 * one thread, in the order the events were queued (which is the stream order per connection and
 * direction).
 *
 * <p>Memory is bounded in total, not per message: queued events plus unfinished messages held by
 * the framers stay within {@code maxQueuedBytes} (the framers may hold half of it). Past that,
 * observation of the largest unfinished messages is given up: their bytes are released, counted
 * as unobserved, reported as a diagnostic, and framing continues after them.
 *
 * <p>A failure of observation (any {@link Throwable}, a bug or a missing class) never reaches the
 * wire: it is reported at once to the {@link SpyListener}s as a
 * {@link SpyNotice.Kind#OBSERVATION_FAILED} notice, the bytes concerned are counted as unobserved,
 * and the log is closed properly at the end.
 */
public final class ObservationPipeline implements WireObserver, AutoCloseable {

    /** Stream-bus message type of spy diagnostics (Player's types are 1..6). */
    public static final int DIAGNOSTIC_TYPE = SpyStreams.DIAGNOSTIC_TYPE;
    /** Failures reported one by one; after that, one report per interval with the running count. */
    private static final long FAILURE_REPORT_INTERVAL_NANOS = 1_000_000_000L;

    private sealed interface Item {
    }

    private record Opened(ConnectionInfo connection, long t) implements Item {
    }

    /**
     * Events of one chunk, decoded; {@code lost} bytes before them, from offset {@code lostAt}, were
     * refused by the queue.
     */
    private record Batch(ConnectionInfo connection, Direction dir, WireEvent[] events, DecodedMessage[] decoded, long t,
            long bytes, long lost, long lostAt, Inflow inflow) implements Item {
    }

    private record Abandoned(ConnectionInfo connection, Direction dir, long offset, int size, long received, long t)
            implements Item {
    }

    private record Failed(ConnectionInfo connection, Direction dir, long offset, String text, long t) implements Item {
    }

    private record Noticed(ConnectionInfo connection, SpyNotice notice, long t) implements Item {
    }

    private record Closed(ConnectionInfo connection, long t, String reason) implements Item {
    }

    private record HoldDone(HoldAction action, long t) implements Item {
    }

    private record HoldChanged(HoldState state, long t) implements Item {
    }

    private record Stop() implements Item {
    }

    private static final ConnectionInfo SPY = new ConnectionInfo(0, 0, "", "", "");

    private record StreamRef(int conn, Direction dir) {
    }

    /** What one connection has waiting in the queue (both directions): its share of the budget. */
    private static final class Inflow {
        final AtomicLong queued = new AtomicLong();
    }

    /** One direction of one connection, framed on its forwarding thread; guarded by its own lock. */
    private final class Stream {
        final ConnectionInfo connection;
        final Direction dir;
        final Inflow inflow;
        final List<WireEvent> out = new ArrayList<>(8);
        PlayerFramer framer;
        /** Bytes handed to this stream so far: the offset after the last chunk. */
        long consumed;
        /** The framer's held bytes as last added to {@link #heldBytes}. */
        volatile long held;
        long abandonedSeen;
        long lost;
        long lostAt = -1;
        boolean done;

        Stream(ConnectionInfo connection, Direction dir, Inflow inflow) {
            this.connection = connection;
            this.dir = dir;
            this.inflow = inflow;
            this.framer = new PlayerFramer(dir, out::add);
        }
    }

    private final StreamBus bus;
    private final PlayerDecoder decoder;
    private final long maxQueuedBytes;
    private final long maxHeldBytes;
    private final LinkedBlockingQueue<Item> queue = new LinkedBlockingQueue<>();
    private final AtomicLong queuedBytes = new AtomicLong();
    private final AtomicLong heldBytes = new AtomicLong();
    private final Map<StreamRef, Stream> streams = new ConcurrentHashMap<>();
    private final Map<Integer, Inflow> inflows = new ConcurrentHashMap<>();
    private final List<SpyListener> listeners = new CopyOnWriteArrayList<>();
    private final Thread worker;
    private volatile boolean closing;
    /** Why observation stopped for good (the observation thread itself failed), or null. */
    private volatile @Nullable String dead;

    private final LongAdder messages = new LongAdder();
    private final LongAdder decodeProblems = new LongAdder();
    private final LongAdder unframedBytes = new LongAdder();
    private final LongAdder droppedBytes = new LongAdder();
    private final LongAdder abandonedMessages = new LongAdder();
    private final LongAdder internalErrors = new LongAdder();
    private final AtomicLong lastFailureReport = new AtomicLong(Long.MIN_VALUE);
    private volatile @Nullable String firstFailure;

    // owned by the worker thread
    private @Nullable SpyRecorder recorder;
    private volatile @Nullable String recorderError;
    private long lastFlushNanos = System.nanoTime();
    private final Set<ConnectionInfo> openConnections = new LinkedHashSet<>();
    private final Map<Integer, MessageKeys> messageKeys = new HashMap<>();

    /**
     * @param recorder       the spy log, or null to record nothing
     * @param maxQueuedBytes how many forwarded bytes observation may hold in total (queued, or in
     *                       unfinished messages) before it drops or gives up observing some
     */
    public ObservationPipeline(StreamBus bus, PlayerDecoder decoder, @Nullable SpyRecorder recorder, long maxQueuedBytes) {
        this.bus = bus;
        this.decoder = decoder;
        this.recorder = recorder;
        this.maxQueuedBytes = maxQueuedBytes;
        this.maxHeldBytes = maxQueuedBytes / 2;
        try {
            ObservationClasses.load(decoder);
        } catch (Throwable t) {
            // Best effort: a class that did not load now fails later, where it is reported and counted.
        }
        this.worker = Thread.ofPlatform().daemon().name("stagecraft-spy-observer").start(this::work);
    }

    /** Hears failures of observation ({@link SpyNotice.Kind#OBSERVATION_FAILED}) as they happen. */
    public ObservationPipeline addListener(SpyListener l) {
        listeners.add(l);
        return this;
    }

    public void removeListener(SpyListener l) {
        listeners.remove(l);
    }

    // ---- called on forwarding threads ------------------------------------------------------------

    @Override
    public void opened(ConnectionInfo connection, long timeNanos) {
        inflows.computeIfAbsent(connection.id(), k -> new Inflow());
        queue.add(new Opened(connection, timeNanos));
    }

    @Override
    public void chunk(ConnectionInfo connection, Direction dir, byte[] data, long timeNanos) {
        chunk(connection, dir, data, 0, data.length, timeNanos);
    }

    /** Frames and decodes on the calling (forwarding) thread; the bytes are not kept. */
    @Override
    public void chunk(ConnectionInfo connection, Direction dir, byte[] data, int off, int len, long timeNanos) {
        if (closing || dead != null) {
            droppedBytes.add(len);
            return;
        }
        StreamRef ref = new StreamRef(connection.id(), dir);
        Stream s = streams.computeIfAbsent(ref,
                k -> new Stream(connection, dir, inflows.computeIfAbsent(connection.id(), i -> new Inflow())));
        synchronized (s) {
            if (s.done || closing) {
                droppedBytes.add(len);
                return;
            }
            long before = s.consumed;
            s.consumed += len;
            try {
                s.framer.accept(data, off, len);
            } catch (Throwable t) {
                s.out.clear();
                droppedBytes.add(len);
                restartFraming(s, before, t);
                publishHeld(s);
                return;
            }
            emit(s, timeNanos);
        }
        if (heldBytes.get() > maxHeldBytes) {
            giveUpLargest(timeNanos);
        }
    }

    /** Decodes and queues what the stream's framer produced; under the stream's lock. */
    private void emit(Stream s, long t) {
        publishHeld(s);
        long abandoned = s.framer.abandonedBytes();
        if (abandoned != s.abandonedSeen) {
            droppedBytes.add(abandoned - s.abandonedSeen);
            s.abandonedSeen = abandoned;
        }
        if (s.out.isEmpty()) {
            return;
        }
        WireEvent[] events = s.out.toArray(WireEvent[]::new);
        s.out.clear();
        long bytes = 0;
        for (WireEvent e : events) {
            bytes += size(e);
        }
        if (!admit(s.inflow, bytes)) {
            if (s.lostAt < 0) {
                s.lostAt = events[0].offset();
            }
            s.lost += bytes;
            droppedBytes.add(bytes);
            return;
        }
        DecodedMessage[] decoded = new DecodedMessage[events.length];
        try {
            for (int i = 0; i < events.length; i++) {
                if (events[i] instanceof WireEvent.Frame f) {
                    decoded[i] = decoder.decode(f);
                }
            }
        } catch (Throwable e) {
            // PlayerDecoder turns a decoder's exceptions into problems; this is an Error (a missing class...).
            release(s.inflow, bytes);
            droppedBytes.add(bytes);
            failure(s.connection, s.dir, events[0].offset(), "decoding failed", e, t);
            return;
        }
        queue.add(new Batch(s.connection, s.dir, events, decoded, t, bytes, s.lost, s.lostAt, s.inflow));
        s.lost = 0;
        s.lostAt = -1;
    }

    /**
     * Whether {@code n} more bytes may wait in the queue: always within the total; once the queue is
     * half full, only within the connection's fair share of it.
     */
    private boolean admit(Inflow inflow, long n) {
        long total = queuedBytes.addAndGet(n);
        long own = inflow.queued.addAndGet(n);
        // never more than half for one connection: a newcomer always finds room
        long share = maxQueuedBytes / Math.max(2, inflows.size());
        if (total + heldBytes.get() <= maxQueuedBytes && (total <= maxQueuedBytes / 2 || own <= share)) {
            return true;
        }
        release(inflow, n);
        return false;
    }

    private void release(Inflow inflow, long n) {
        queuedBytes.addAndGet(-n);
        inflow.queued.addAndGet(-n);
    }

    private void publishHeld(Stream s) {
        long h = s.framer.heldBytes();
        if (h != s.held) {
            heldBytes.addAndGet(h - s.held);
            s.held = h;
        }
    }

    /**
     * Unfinished messages hold more than their half of the budget: give up observing the largest
     * ones (their streams may be stalled, their threads blocked in a read) until they fit again.
     */
    private void giveUpLargest(long t) {
        while (heldBytes.get() > maxHeldBytes) {
            Stream largest = null;
            for (Stream s : streams.values()) {
                if (s.held > MessageHeader.SIZE && (largest == null || s.held > largest.held)) {
                    largest = s;
                }
            }
            if (largest == null) {
                return;
            }
            synchronized (largest) {
                PlayerFramer f = largest.framer;
                long offset = f.pendingMessageOffset();
                int size = f.pendingMessageSize();
                long received = f.heldBytes();
                if (largest.done || f.abandon() == 0) {
                    publishHeld(largest);
                    return; // nothing this stream holds can be given up (cannot happen while it holds a payload)
                }
                abandonedMessages.increment();
                emit(largest, t);
                queue.add(new Abandoned(largest.connection, largest.dir, offset, size, received, t));
            }
        }
    }

    /**
     * The framer itself failed: its state cannot be trusted, so a new one takes over after the
     * bytes handed in so far, looking for the next header.
     */
    private void restartFraming(Stream s, long offset, Throwable t) {
        s.framer = new PlayerFramer(s.dir, s.out::add);
        s.framer.gap(s.consumed, "framing failed");
        s.abandonedSeen = 0;
        failure(s.connection, s.dir, offset, "framing failed", t, WallClock.nowNanos());
    }

    /** Recorded in the log and published as a {@link SpyDiagnostic} of the server-to-client stream, at offset 0. */
    @Override
    public void notice(SpyNotice notice, long timeNanos) {
        queue.add(new Noticed(notice.connection(), notice, timeNanos));
    }

    /** Both directions have ended: the framers report what they left unfinished, then the close is queued. */
    @Override
    public void closed(ConnectionInfo connection, long timeNanos, String reason) {
        for (Direction d : Direction.values()) {
            Stream s = streams.remove(new StreamRef(connection.id(), d));
            if (s == null) {
                continue;
            }
            synchronized (s) {
                if (s.done) {
                    continue;
                }
                s.done = true;
                try {
                    s.framer.end();
                } catch (Throwable t) {
                    s.out.clear();
                    failure(connection, d, s.consumed, "ending the framing failed", t, timeNanos);
                }
                emit(s, timeNanos);
                heldBytes.addAndGet(-s.held);
                s.held = 0;
                if (s.lost > 0) {
                    queue.add(new Batch(connection, d, new WireEvent[0], new DecodedMessage[0], timeNanos, 0, s.lost,
                            s.lostAt, s.inflow));
                }
            }
        }
        queue.add(new Closed(connection, timeNanos, reason));
    }

    /** Never dropped like chunks: they are few and the log must rebuild what Player received. */
    @Override
    public void holdAction(HoldAction action, long timeNanos) {
        queue.add(new HoldDone(action, timeNanos));
    }

    @Override
    public void holdState(HoldState state, long timeNanos) {
        queue.add(new HoldChanged(state, timeNanos));
    }

    // ---- status --------------------------------------------------------------------------------

    public long messages() {
        return messages.sum();
    }

    public long decodeProblems() {
        return decodeProblems.sum();
    }

    public long unframedBytes() {
        return unframedBytes.sum();
    }

    /**
     * Forwarded bytes that were not observed: skipped because observation fell behind, given up
     * because unfinished messages held too much memory, or lost to a failure of observation.
     */
    public long droppedBytes() {
        return droppedBytes.sum();
    }

    /** Unfinished messages whose observation was given up to keep memory bounded. */
    public long abandonedMessages() {
        return abandonedMessages.sum();
    }

    /** How often observation failed (a bug, a missing class...); each is reported to the listeners. */
    public long internalErrors() {
        return internalErrors.sum();
    }

    /** The first failure of observation, as reported, or null if there was none. */
    public @Nullable String failure() {
        return firstFailure;
    }

    /** Why the spy log stopped, or null while it is fine (or there is none). */
    public @Nullable String recorderError() {
        return recorderError;
    }

    /** Bytes observation holds right now (queued events and unfinished messages). */
    public long heldBytes() {
        return queuedBytes.get() + heldBytes.get();
    }

    /** Processes everything queued so far, then stops and closes the recorder. */
    @Override
    public void close() throws InterruptedException {
        closing = true;
        queue.add(new Stop());
        worker.join();
    }

    // ---- failures ------------------------------------------------------------------------------

    /**
     * Counts a failure and reports it at once (the first ones; then once a second with the count),
     * to the listeners and, through the observation thread, to the log and the bus.
     */
    private void failure(ConnectionInfo c, Direction dir, long offset, String what, Throwable t, long time) {
        internalErrors.increment();
        String text = "observation failed on connection " + c.id() + (c.client().isEmpty() ? "" : " from " + c.client())
                + " (" + what + ": " + describe(t) + "); forwarding goes on, the bytes concerned are counted as unobserved";
        report(c, text);
        queue.add(new Failed(c, dir, offset, text, time));
    }

    private void report(ConnectionInfo c, String text) {
        long now = System.nanoTime();
        long last = lastFailureReport.get();
        long count = internalErrors.sum();
        if (firstFailure == null) {
            firstFailure = text;
        }
        if (count > 3 && last != Long.MIN_VALUE && now - last < FAILURE_REPORT_INTERVAL_NANOS) {
            return;
        }
        if (!lastFailureReport.compareAndSet(last, now)) {
            return;
        }
        String line = count > 1 ? text + " [" + count + " observation failures so far]" : text;
        SpyNotice n = new SpyNotice(c, SpyNotice.Kind.OBSERVATION_FAILED, line);
        for (SpyListener l : listeners) {
            try {
                l.notice(n);
            } catch (Throwable ignored) {
                // a listener's failure must not stop the reporting of ours
            }
        }
    }

    static String describe(Throwable t) {
        String m = t.getMessage();
        return t.getClass().getName() + (m == null ? "" : ": " + m);
    }

    // ---- the observation thread ------------------------------------------------------------------

    private void work() {
        try {
            loop();
        } catch (Throwable t) {
            internalErrors.increment();
            dead = "observation stopped: " + describe(t);
            report(SPY, dead + "; forwarding goes on, nothing more is observed");
        } finally {
            finish();
        }
    }

    private void loop() throws InterruptedException {
        List<Item> items = new ArrayList<>(256);
        while (true) {
            Item first = queue.poll(1, TimeUnit.SECONDS);
            if (first != null) {
                items.add(first);
                queue.drainTo(items, 255);
            }
            for (Item item : items) {
                if (item instanceof Stop) {
                    items.clear();
                    return;
                }
                handleSafely(item);
            }
            items.clear();
            if (System.nanoTime() - lastFlushNanos > 1_000_000_000L) {
                lastFlushNanos = System.nanoTime();
                recordQuietly(r -> r.flush());
            }
        }
    }

    /** Stops: what is still queued is processed, unfinished streams are reported, the log closed. */
    private void finish() {
        closing = true;
        drainQueue();
        // Connections still open when observation stops: report what they left unfinished.
        long now = WallClock.nowNanos();
        for (Stream s : streams.values()) {
            synchronized (s) {
                if (s.done) {
                    continue;
                }
                s.done = true;
                try {
                    s.framer.end();
                } catch (Throwable t) {
                    s.out.clear();
                }
                emit(s, now);
            }
        }
        drainQueue();
        for (ConnectionInfo c : openConnections) {
            recordQuietly(r -> r.closed(c, now, "observation stopped"));
        }
        openConnections.clear();
        streams.clear();
        recordQuietly(SpyRecorder::close);
        recorder = null;
    }

    private void drainQueue() {
        for (Item item = queue.poll(); item != null; item = queue.poll()) {
            if (dead == null) {
                handleSafely(item);
            } else if (item instanceof Batch b) {
                droppedBytes.add(b.bytes());
            }
        }
    }

    private void handleSafely(Item item) {
        try {
            handle(item);
        } catch (Throwable t) {
            if (item instanceof Batch b) {
                droppedBytes.add(b.bytes());
                release(b.inflow(), b.bytes());
                failure(b.connection(), b.dir(), b.events().length > 0 ? b.events()[0].offset() : 0,
                        "publishing or recording failed", t, b.t());
            } else {
                internalErrors.increment();
                report(SPY, "observation failed (" + describe(t) + "); forwarding goes on");
            }
        }
    }

    private void handle(Item item) {
        switch (item) {
            case Opened o -> {
                openConnections.add(o.connection());
                record(r -> r.opened(o.connection(), o.t()));
            }
            case Batch b -> {
                if (b.lost() > 0) {
                    diagnostic(b.connection(), b.dir(), b.lostAt(), b.lost()
                            + " forwarded bytes were not observed (observer queue full)", b.t());
                }
                WireEvent[] events = b.events();
                for (int i = 0; i < events.length; i++) {
                    event(b.connection(), b.dir(), events[i], b.decoded()[i], b.t());
                }
                release(b.inflow(), b.bytes());
            }
            case Abandoned a -> diagnostic(a.connection(), a.dir(), a.offset(), String.format(Locale.ROOT,
                    "observation of the %d-byte message at offset %d was given up after %d bytes of it: unfinished"
                            + " messages held more than %.1f MiB of the spy's observation memory; its bytes are not observed",
                    MessageHeader.SIZE + a.size(), a.offset(), a.received(), maxHeldBytes / 1048576.0),
                    a.t());
            case Failed f -> diagnostic(f.connection(), f.dir(), f.offset(), f.text(), f.t());
            case Noticed n -> diagnostic(n.connection(), Direction.SERVER_TO_CLIENT, 0, n.notice().text(), n.t());
            case Closed cl -> {
                openConnections.remove(cl.connection());
                messageKeys.remove(cl.connection().id());
                inflows.remove(cl.connection().id());
                record(r -> r.closed(cl.connection(), cl.t(), cl.reason()));
                bus.release(cl.connection().client()); // its streams end here: the bus forgets them (issue 17)
            }
            case HoldDone h -> {
                record(r -> r.hold(h.action().toEntry(h.t())));
                bus.publish(new StreamMessage(HoldStreams.actionKey(h.action()), h.t(), h.action()));
            }
            case HoldChanged h -> {
                HoldState s = h.state();
                record(r -> r.hold(new HoldEntry(h.t(), 0, 0, s.held() ? HoldEntry.Action.HOLD_ON : HoldEntry.Action.HOLD_OFF,
                        0, 0, new byte[0], s.description())));
                bus.publish(new StreamMessage(HoldStreams.STATE, h.t(), s));
            }
            case Stop s -> {
                // handled by the loop
            }
        }
    }

    private void event(ConnectionInfo c, Direction dir, WireEvent e, DecodedMessage m, long t) {
        if (recorder != null) {
            record(r -> r.wire(c, dir, e, t));
        }
        switch (e) {
            case WireEvent.Banner b -> {
                // the ident is in the log; tools see the connection through its messages
            }
            case WireEvent.Frame f -> {
                messages.increment();
                MessageHeader h = f.header();
                MessageKeys keys = messageKeys.get(c.id());
                if (keys == null || !keys.isFor(c)) {
                    keys = new MessageKeys(c);
                    messageKeys.put(c.id(), keys);
                }
                bus.publish(new StreamMessage(keys.of(dir, h), t,
                        new SpyMessage(c, dir, f.offset(), m)));
                if (m.hasProblem()) {
                    decodeProblems.increment();
                    diagnostic(c, dir, f.offset() + MessageHeader.SIZE + Math.max(0, m.problem().payloadOffset()),
                            m.problem().reason(), t);
                }
            }
            case WireEvent.Unframed u -> {
                unframedBytes.add(u.length());
                diagnosticOnBus(c, dir, u.offset(), u.reason(), t);
            }
        }
    }

    private static long size(WireEvent e) {
        return switch (e) {
            case WireEvent.Frame f -> f.wireSize();
            case WireEvent.Unframed u -> u.length();
            case WireEvent.Banner b -> PlayerFramer.IDENT_LENGTH;
        };
    }

    private void diagnostic(ConnectionInfo c, Direction dir, long offset, String text, long t) {
        record(r -> r.diagnostic(c, dir, offset, text, t));
        diagnosticOnBus(c, dir, offset, text, t);
    }

    private void diagnosticOnBus(ConnectionInfo c, Direction dir, long offset, String text, long t) {
        bus.publish(new StreamMessage(SpyStreams.diagnosticKey(c, dir), t, new SpyDiagnostic(c, dir, offset, text)));
    }

    @FunctionalInterface
    private interface RecorderCall {
        void apply(SpyRecorder r) throws IOException;
    }

    /**
     * A full disk (an IOException) stops logging and says why; any other failure of the log (a bug,
     * a missing class) does too, and is thrown on so that what it was recording counts as
     * unobserved. Either way what was written is closed properly.
     */
    private void record(RecorderCall call) {
        SpyRecorder recorder = this.recorder;
        if (recorder == null) {
            return;
        }
        try {
            call.apply(recorder);
        } catch (Throwable e) {
            recorderError = "spy log stopped: " + (e instanceof IOException ? String.valueOf(e.getMessage()) : describe(e));
            try {
                recorder.close();
            } catch (Throwable ignored) {
                // already failing; the first error is the one reported
            }
            this.recorder = null;
            if (e instanceof RuntimeException re) {
                throw re;
            }
            if (e instanceof Error er) {
                throw er;
            }
        }
    }

    /** For the last steps, where a failure has nothing left to stop. */
    private void recordQuietly(RecorderCall call) {
        try {
            record(call);
        } catch (Throwable e) {
            internalErrors.increment();
            report(SPY, String.valueOf(recorderError)); // set by record() before it throws
        }
    }
}
