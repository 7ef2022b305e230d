package org.stagecraft.spy.proxy;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.time.Duration;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;

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
import org.stagecraft.spy.hold.WorldChange;
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
 * direction). It works in rounds: it takes everything queued, publishes it to the bus in one
 * {@link StreamBus#publishAll} (one hand-over per subscription per round, not per message) and
 * sleeps until the next tick ({@value #TICK_MILLIS} ms) unless {@value #WAKE_BYTES} bytes or a
 * waiting forwarding thread wake it earlier. At a robot's rates this is what costs: waking a thread
 * per message cost more CPU than framing, decoding, publishing and logging it.
 *
 * <p><b>Complete observation</b> ({@link #observationWait(Duration)}): when the queue has no room
 * for a chunk, the forwarding thread waits — after the chunk went out, before its next read — while
 * observation is making progress, so a burst faster than observation is slowed to observation's pace
 * by TCP's own flow control instead of being left out of the log. The wire never waits for a part
 * that is stuck (a hung disk, a bug): once observation has made no progress for the wait limit, the
 * chunk is dropped from observation as before, and no chunk waits again until observation moves.
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

    private record WorldChanged(WorldChange change, long t) implements Item {
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
    private final long flowBytes;
    /**
     * The observation memory bound of {@code stagecraft spy} and a Robot Session (queued events and
     * unfinished messages, see the constructor): with complete observation the queue only has to keep
     * the observation thread busy, and what waits in it is held as decoded objects, several times the
     * wire bytes, so a small bound keeps the spy's heap (and its resident memory) small.
     */
    public static final long DEFAULT_MAX_QUEUED_BYTES = 24L << 20;
    /** Default {@link #observationWait(Duration)}: long enough for a log's fsync, short for a hung disk. */
    public static final Duration DEFAULT_OBSERVATION_WAIT = Duration.ofSeconds(1);
    /**
     * Queued bytes past which a forwarding thread waits for observation (complete observation): enough
     * to keep the observation thread busy, small enough to stay in the young generation. Measured at
     * full speed (bench spy, ten rounds each): 1 MiB took 1.69 µs of CPU per message and relayed 313
     * MB/s (medians), 4 MiB 2.05 µs and 251 MB/s, 16 MiB worse again; what waits longer is copied by
     * more young collections.
     */
    static final long FLOW_BYTES = 1L << 20;
    /** How long a forwarded chunk waits for room within the flow limit before it is taken past it ({@link #take}). */
    static final long OVERDUE_NANOS = TimeUnit.MILLISECONDS.toNanos(50);
    /** How long the observation thread sleeps between rounds when nothing wakes it. */
    static final long TICK_MILLIS = 50;
    /** Queued bytes that wake the observation thread before its tick. */
    static final long WAKE_BYTES = 256 << 10;
    /**
     * How often the recorder is flushed while there is something new in it: what observation has
     * recorded reaches the log file (where a killed process leaves it) within this, plus up to a
     * {@linkplain #TICK_MILLIS tick} before observation takes it up. Shorter than a tick, so that every
     * round of a steady flow ends with a flush.
     */
    static final long LOG_WRITE_NANOS = TimeUnit.MILLISECONDS.toNanos(TICK_MILLIS - 10);
    /** How often the recorder is flushed when nothing new was recorded (it forces the file to the disk). */
    static final long LOG_FLUSH_NANOS = TimeUnit.SECONDS.toNanos(1);

    private final ConcurrentLinkedQueue<Item> queue = new ConcurrentLinkedQueue<>();
    /** The observation thread is between rounds (parked until its tick or a wake-up). */
    private volatile boolean idle;
    private final AtomicLong queuedBytes = new AtomicLong();
    /** Bytes of queued events the observation thread has finished with: its progress, for waiting forwarders. */
    private final AtomicLong observedProgress = new AtomicLong();
    private final ReentrantLock roomLock = new ReentrantLock();
    private final Condition room = roomLock.newCondition();
    private final AtomicInteger waiting = new AtomicInteger();
    /** Observation made no progress for the wait limit: chunks are dropped without waiting until it moves. */
    private volatile boolean stalled;
    private volatile long observationWaitNanos = DEFAULT_OBSERVATION_WAIT.toNanos();
    private final LongAdder waitNanos = new LongAdder();
    private final LongAdder stalls = new LongAdder();
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
    /** The recorder as given, also after it stopped: it says what reached the log ({@link SpyRecorder#logged()}). */
    private final @Nullable SpyRecorder log;
    /** Why the log stopped, or null. */
    private volatile @Nullable String recorderError;
    private final long startNanos = System.nanoTime();
    /** When the log stopped, on {@link System#nanoTime()}'s scale. */
    private volatile long recorderStoppedNanos;
    /** Wire events framed by observation (banners, Player messages, unframed pieces) and their bytes. */
    private final LongAdder framedMessages = new LongAdder();
    private final LongAdder framedBytes = new LongAdder();
    /** The same, since the log stopped: what is not in it when the recorder cannot say what is. */
    private final LongAdder framedMessagesAfterStop = new LongAdder();
    private final LongAdder framedBytesAfterStop = new LongAdder();
    private long lastFlushNanos = System.nanoTime();
    /** Something was recorded since the last flush. */
    private boolean recordedSinceFlush;
    private final Set<ConnectionInfo> openConnections = new LinkedHashSet<>();
    /** What this round publishes, in order; handed to the bus at the end of the round, every 256 items, before a release. */
    private final List<StreamMessage> outbox = new ArrayList<>(512);
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
        this.log = recorder;
        this.maxQueuedBytes = maxQueuedBytes;
        this.maxHeldBytes = maxQueuedBytes / 2;
        this.flowBytes = Math.min(FLOW_BYTES, maxQueuedBytes / 2);
        try {
            ObservationClasses.load(decoder);
        } catch (Throwable t) {
            // Best effort: a class that did not load now fails later, where it is reported and counted.
        }
        this.worker = Thread.ofPlatform().daemon().name("spy-observer").start(this::work);
    }

    /** Hears failures of observation ({@link SpyNotice.Kind#OBSERVATION_FAILED}) as they happen. */
    public ObservationPipeline addListener(SpyListener l) {
        listeners.add(l);
        return this;
    }

    public void removeListener(SpyListener l) {
        listeners.remove(l);
    }

    /**
     * How long a forwarding thread may wait for room in the queue while observation makes no
     * progress ({@link #DEFAULT_OBSERVATION_WAIT}); {@link Duration#ZERO} never waits: what does not
     * fit is dropped from observation at once (best effort, the wire never slowed).
     */
    public ObservationPipeline observationWait(Duration limit) {
        this.observationWaitNanos = Math.max(0, limit.toNanos());
        return this;
    }

    // ---- called on forwarding threads ------------------------------------------------------------

    @Override
    public void opened(ConnectionInfo connection, long timeNanos) {
        inflows.computeIfAbsent(connection.id(), k -> new Inflow());
        enqueue(new Opened(connection, timeNanos));
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
        long reserved = reserve(s.inflow, len);
        synchronized (s) {
            if (s.done || closing) {
                unreserve(s.inflow, reserved);
                droppedBytes.add(len);
                return;
            }
            long before = s.consumed;
            s.consumed += len;
            try {
                s.framer.accept(data, off, len);
            } catch (Throwable t) {
                unreserve(s.inflow, reserved);
                s.out.clear();
                droppedBytes.add(len);
                restartFraming(s, before, t);
                publishHeld(s);
                return;
            }
            emit(s, timeNanos, reserved);
        }
        if (heldBytes.get() > maxHeldBytes) {
            giveUpLargest(timeNanos);
        }
    }

    /** Decodes and queues what the stream's framer produced; under the stream's lock. */
    private void emit(Stream s, long t) {
        emit(s, t, 0);
    }

    /**
     * As {@link #emit(Stream, long)}, with {@code reserved} bytes of room already taken for this
     * chunk ({@link #reserve}): the events are queued whatever their size (a message completed now
     * moves its earlier bytes from the framer's holdings to the queue, so the total stays bounded),
     * and the reservation is settled against what was queued.
     */
    private void emit(Stream s, long t, long reserved) {
        publishHeld(s);
        long abandoned = s.framer.abandonedBytes();
        if (abandoned != s.abandonedSeen) {
            droppedBytes.add(abandoned - s.abandonedSeen);
            s.abandonedSeen = abandoned;
        }
        if (s.out.isEmpty()) {
            unreserve(s.inflow, reserved);
            return;
        }
        WireEvent[] events = s.out.toArray(WireEvent[]::new);
        s.out.clear();
        long bytes = 0;
        for (WireEvent e : events) {
            bytes += size(e);
        }
        if (reserved > 0) {
            settle(s.inflow, reserved, bytes);
        } else if (!admit(s.inflow, bytes)) {
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
        enqueue(new Batch(s.connection, s.dir, events, decoded, t, bytes, s.lost, s.lostAt, s.inflow));
        s.lost = 0;
        s.lostAt = -1;
    }

    /**
     * Takes room for a chunk of {@code n} bytes before it is framed, waiting on the forwarding
     * thread — after the chunk went out, before the next read — while the queue is full and
     * observation makes progress. Returns the bytes taken: {@code n}, or 0 when observation is
     * best-effort ({@link #observationWait} zero), closing, or stalled (no progress for the wait
     * limit: then {@link #admit} decides afterwards, and what does not fit is dropped).
     */
    private long reserve(Inflow inflow, long n) {
        long limit = observationWaitNanos;
        if (limit <= 0 || closing || dead != null) {
            return 0;
        }
        if (take(inflow, n)) {
            return n;
        }
        if (stalled) {
            return 0;
        }
        long start = System.nanoTime();
        long progress = observedProgress.get();
        long lastMove = start;
        boolean gaveUp = false;
        waiting.incrementAndGet();
        roomLock.lock();
        try {
            wake();
            long before = progress;
            while (!closing && dead == null && !stalled) {
                long now = System.nanoTime();
                long p = observedProgress.get();
                // overdue only while observation moves: a stuck one gets no more than the flow limit
                if (take(inflow, n, now - start >= OVERDUE_NANOS && p != before)) {
                    return n;
                }
                if (p != progress) {
                    progress = p;
                    lastMove = now;
                } else if (now - lastMove >= limit) {
                    stalled = true;
                    stalls.increment();
                    gaveUp = true;
                    break;
                }
                room.awaitNanos(Math.min(limit - (now - lastMove), TimeUnit.MILLISECONDS.toNanos(TICK_MILLIS)));
            }
            return 0;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 0;
        } finally {
            roomLock.unlock();
            waiting.decrementAndGet();
            waitNanos.add(System.nanoTime() - start);
            if (gaveUp) {
                tell(new SpyNotice(SPY, SpyNotice.Kind.OBSERVATION_STALLED, String.format(Locale.ROOT,
                        "observation made no progress for %.1f s (a hung disk? a stuck log?): forwarding goes on without"
                                + " waiting for it, and what it cannot take is not observed until it moves again [%d stalls so far]",
                        limit / 1e9, stalls.sum())));
            }
        }
    }

    /**
     * Takes {@code n} bytes of room within the flow limit ({@code flowBytes}: {@link #FLOW_BYTES}, at most half
     * the memory bound): complete observation
     * keeps the queue that short, so what waits in it (decoded, several times its wire size) stays
     * small and young for the garbage collector; the larger bound of the constructor is for
     * best-effort observation and a stalled one, where {@link #admit} decides.
     */
    private boolean take(Inflow inflow, long n) {
        return take(inflow, n, false);
    }

    /**
     * As {@link #take(Inflow, long)}; {@code overdue}: the chunk has waited {@link #OVERDUE_NANOS}
     * already while observation made progress, and is taken past the flow limit, up to twice it.
     * Waiting forwarders race for the room observation makes, with each other and with those that
     * read next: without this, a chunk could wait far longer, relayed and not yet observed, which is
     * what a crash then takes from the log (docs/spy-log.md). A forwarding thread holds one chunk, so
     * the overdue ones (a chunk each) fit in the second flow limit unless there are many connections.
     */
    private boolean take(Inflow inflow, long n, boolean overdue) {
        long total = queuedBytes.addAndGet(n);
        if (total == n || total <= (overdue ? 2 * flowBytes : flowBytes) && total + heldBytes.get() <= maxQueuedBytes) {
            inflow.queued.addAndGet(n);
            return true; // an empty queue always takes one chunk, whatever its size
        }
        queuedBytes.addAndGet(-n);
        return false;
    }

    private void unreserve(Inflow inflow, long reserved) {
        if (reserved > 0) {
            release(inflow, reserved);
            signalRoom();
        }
    }

    /** Turns a reservation of {@code reserved} bytes into the {@code bytes} actually queued. */
    private void settle(Inflow inflow, long reserved, long bytes) {
        if (bytes != reserved) {
            queuedBytes.addAndGet(bytes - reserved);
            inflow.queued.addAndGet(bytes - reserved);
        }
    }

    /** The observation thread is done with {@code b} (handled or failed): its room is free, and that is progress. */
    private void observed(Batch b) {
        release(b.inflow(), b.bytes());
        madeProgress(b.bytes());
    }

    /** Called by the observation thread when it has released queued bytes: progress for waiting forwarders. */
    private void madeProgress(long bytes) {
        observedProgress.addAndGet(bytes);
        stalled = false;
    }

    private void signalRoom() {
        if (waiting.get() > 0) {
            roomLock.lock();
            try {
                room.signalAll();
            } finally {
                roomLock.unlock();
            }
        }
    }

    private void enqueue(Item item) {
        queue.add(item);
        if (item instanceof Stop || queuedBytes.get() >= WAKE_BYTES) {
            wake();
        }
    }

    private void wake() {
        if (idle) {
            LockSupport.unpark(worker);
        }
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
                enqueue(new Abandoned(largest.connection, largest.dir, offset, size, received, t));
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
        enqueue(new Noticed(notice.connection(), notice, timeNanos));
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
                    enqueue(new Batch(connection, d, new WireEvent[0], new DecodedMessage[0], timeNanos, 0, s.lost,
                            s.lostAt, s.inflow));
                }
            }
        }
        enqueue(new Closed(connection, timeNanos, reason));
    }

    /** Never dropped like chunks: they are few and the log must rebuild what Player received. */
    @Override
    public void holdAction(HoldAction action, long timeNanos) {
        enqueue(new HoldDone(action, timeNanos));
    }

    @Override
    public void holdState(HoldState state, long timeNanos) {
        enqueue(new HoldChanged(state, timeNanos));
    }

    @Override
    public void worldChanged(WorldChange change, long timeNanos) {
        enqueue(new WorldChanged(change, timeNanos));
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

    /** How long forwarding threads waited in all for observation to make room (complete observation). */
    public Duration waitedForObservation() {
        return Duration.ofNanos(waitNanos.sum());
    }

    /** How often observation made no progress for the wait limit, so that chunks were dropped instead. */
    public long stalls() {
        return stalls.sum();
    }

    /**
     * What complete observation did to the wire, for a summary line, each part after {@code sep}:
     * how long forwarding waited for observation and how often it stalled; empty when neither happened.
     */
    public String waitingSummary(String sep) {
        StringBuilder b = new StringBuilder();
        long waited = waitedForObservation().toMillis();
        if (waited > 0) { // a change of the wire's timing: said wherever the spy's totals are
            b.append(sep).append(String.format(Locale.ROOT, "forwarding waited %.1f s for observation", waited / 1000.0));
        }
        if (stalls() > 0) {
            b.append(sep).append(stalls()).append(" observation stalls (bytes left out after waiting the limit)");
        }
        return b.toString();
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

    /**
     * Why the spy log stopped, when, and what was relayed but is not in the log, or null while it is
     * fine (or there is none): e.g. "spy log stopped at 12.3 s: No space left on device; 5120
     * messages (3.1 MB) relayed are not in the log". The time is since observation started; the
     * messages are wire events as observation framed them (banners, Player messages, unframed
     * pieces) with their wire bytes; bytes observation did not see ({@link #droppedBytes()}) are not
     * in the log either and counted apart. Final once the pipeline is closed (what was still on its
     * way to the log counts too).
     */
    public @Nullable String recorderError() {
        String why = recorderError;
        if (why == null) {
            return null;
        }
        long messages;
        long bytes;
        SpyRecorder.Logged in = null;
        try {
            SpyRecorder l = log;
            in = l == null ? null : l.logged();
        } catch (RuntimeException e) {
            // cannot tell: what came after the stop is counted instead
        }
        if (in != null) {
            messages = framedMessages.sum() - in.messages();
            bytes = framedBytes.sum() - in.bytes();
        } else {
            messages = framedMessagesAfterStop.sum();
            bytes = framedBytesAfterStop.sum();
        }
        return String.format(Locale.ROOT, "spy log stopped at %.1f s: %s; %d messages (%s) relayed %sare not in the log",
                (recorderStoppedNanos - startNanos) / 1e9, why, Math.max(0, messages), amount(Math.max(0, bytes)),
                in != null ? "" : "after that ");
    }

    private static String amount(long bytes) {
        if (bytes < 10_000) {
            return bytes + " bytes";
        }
        return bytes < 1_000_000 ? String.format(Locale.ROOT, "%.1f kB", bytes / 1e3)
                : String.format(Locale.ROOT, "%.1f MB", bytes / 1e6);
    }

    /** Bytes observation holds right now (queued events and unfinished messages). */
    public long heldBytes() {
        return queuedBytes.get() + heldBytes.get();
    }

    /** Processes everything queued so far, then stops and closes the recorder. */
    @Override
    public void close() throws InterruptedException {
        closing = true;
        signalRoom();
        enqueue(new Stop());
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
        enqueue(new Failed(c, dir, offset, text, time));
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
        tell(new SpyNotice(c, SpyNotice.Kind.OBSERVATION_FAILED, line));
    }

    private void tell(SpyNotice n) {
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

    private void loop() {
        while (true) {
            int n = 0;
            for (Item item = queue.poll(); item != null; item = queue.poll()) {
                if (item instanceof Stop) {
                    sendOutbox();
                    return;
                }
                handleSafely(item);
                if (++n % 256 == 0) {
                    sendOutbox();
                    signalRoom();
                    flushInTime(); // a round that never runs dry still writes the log in time
                }
            }
            sendOutbox();
            signalRoom();
            flushInTime();
            idle = true;
            if (queue.isEmpty()) { // a producer that saw idle == false queued before this check
                LockSupport.parkNanos(this, TimeUnit.MILLISECONDS.toNanos(TICK_MILLIS));
            }
            idle = false;
        }
    }

    /**
     * Flushes the recorder when what it was given last is {@link #LOG_WRITE_NANOS} old, and at
     * least every {@link #LOG_FLUSH_NANOS}: the crash window of the log (docs/spy-log.md).
     */
    private void flushInTime() {
        long now = System.nanoTime();
        if (now - lastFlushNanos >= (recordedSinceFlush ? LOG_WRITE_NANOS : LOG_FLUSH_NANOS)) {
            lastFlushNanos = now;
            recordedSinceFlush = false;
            recordQuietly(r -> r.flush());
        }
    }

    /** Hands this round's messages to the bus, in order. */
    private void sendOutbox() {
        if (!outbox.isEmpty()) {
            try {
                bus.publishAll(outbox);
            } finally {
                outbox.clear();
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
        try {
            sendOutbox();
        } catch (Throwable ignored) {
            // stopping: nothing left to tell (sendOutbox has cleared the outbox)
        }
    }

    private void handleSafely(Item item) {
        try {
            handle(item);
        } catch (Throwable t) {
            if (item instanceof Batch b) {
                droppedBytes.add(b.bytes());
                observed(b);
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
                observed(b);
            }
            case Abandoned a -> diagnostic(a.connection(), a.dir(), a.offset(), String.format(Locale.ROOT,
                    "observation of the %d-byte message at offset %d was given up after %d bytes of it: unfinished"
                            + " messages held more than %.1f MiB of the spy's observation memory; its bytes are not observed",
                    MessageHeader.SIZE + a.size(), a.offset(), a.received(), maxHeldBytes / 1048576.0),
                    a.t());
            case Failed f -> diagnostic(f.connection(), f.dir(), f.offset(), f.text(), f.t());
            case Noticed n -> diagnostic(n.connection(), Direction.SERVER_TO_CLIENT, 0, n.notice().text(), n.t());
            case Closed cl -> {
                sendOutbox(); // the connection's last messages reach the bus before its close is recorded, and released
                openConnections.remove(cl.connection());
                messageKeys.remove(cl.connection().id());
                inflows.remove(cl.connection().id());
                record(r -> r.closed(cl.connection(), cl.t(), cl.reason()));
                bus.release(cl.connection().client()); // its streams end here: the bus forgets them (issue 17)
            }
            case HoldDone h -> {
                record(r -> r.hold(h.action().toEntry(h.t())));
                outbox.add(new StreamMessage(HoldStreams.actionKey(h.action()), h.t(), h.action()));
            }
            case HoldChanged h -> {
                HoldState s = h.state();
                record(r -> r.hold(new HoldEntry(h.t(), 0, 0, s.held() ? HoldEntry.Action.HOLD_ON : HoldEntry.Action.HOLD_OFF,
                        0, 0, new byte[0], s.description())));
                outbox.add(new StreamMessage(HoldStreams.STATE, h.t(), s));
            }
            case WorldChanged w -> {
                WorldChange c = w.change();
                record(r -> r.hold(new HoldEntry(w.t(), 0, 0, c.frozen() ? HoldEntry.Action.WORLD_FROZEN
                        : HoldEntry.Action.WORLD_THAWED, 0, 0, new byte[0], c.text())));
                outbox.add(new StreamMessage(HoldStreams.WORLD, w.t(), c));
            }
            case Stop s -> {
                // handled by the loop
            }
        }
    }

    private void event(ConnectionInfo c, Direction dir, WireEvent e, DecodedMessage m, long t) {
        framedMessages.increment();
        framedBytes.add(size(e));
        if (recorder != null) {
            record(r -> r.wire(c, dir, e, t));
        } else if (recorderError != null) {
            framedMessagesAfterStop.increment();
            framedBytesAfterStop.add(size(e));
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
                outbox.add(new StreamMessage(keys.of(dir, h), t, new SpyMessage(c, dir, f.offset(), m)));
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
        outbox.add(new StreamMessage(SpyStreams.diagnosticKey(c, dir), t, new SpyDiagnostic(c, dir, offset, text)));
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
            recordedSinceFlush = true;
        } catch (Throwable e) {
            recorderStoppedNanos = System.nanoTime();
            recorderError = e instanceof IOException ? String.valueOf(e.getMessage()) : describe(e);
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
            report(SPY, String.valueOf(recorderError())); // set by record() before it throws
        }
    }
}
