package org.stagecraft.spy.proxy;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;

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
 * Turns what the spy forwarded into messages: frames each connection's directions, decodes,
 * publishes on the stream bus and records to the spy log, on one thread of its own. The
 * forwarding threads only enqueue a copy; the queue is bounded by bytes, and when it is full the
 * chunk is dropped from observation (never from the wire), counted, and the framer is told about
 * the gap so the following messages are still found at the right offsets.
 */
public final class ObservationPipeline implements WireObserver, AutoCloseable {

    /** Stream-bus message type of spy diagnostics (Player's types are 1..6). */
    public static final int DIAGNOSTIC_TYPE = SpyStreams.DIAGNOSTIC_TYPE;

    private sealed interface Item {
        ConnectionInfo connection();
    }

    private record Opened(ConnectionInfo connection, long t) implements Item {
    }

    private record Chunk(ConnectionInfo connection, Direction dir, byte[] data, long t, long lostBefore)
            implements Item {
    }

    private record Noticed(ConnectionInfo connection, SpyNotice notice, long t) implements Item {
    }

    private record Closed(ConnectionInfo connection, long t, String reason) implements Item {
    }

    private record HoldDone(HoldAction action, long t) implements Item {
        @Override
        public ConnectionInfo connection() {
            return action.connection();
        }
    }

    /** The hold is the spy's, not a connection's: its connection() is the placeholder below. */
    private record HoldChanged(HoldState state, long t) implements Item {
        @Override
        public ConnectionInfo connection() {
            return SPY;
        }
    }

    private static final ConnectionInfo SPY = new ConnectionInfo(0, 0, "", "", "");

    private record StreamRef(int conn, Direction dir) {
    }

    private final StreamBus bus;
    private final PlayerDecoder decoder;
    private final long maxQueuedBytes;
    private final LinkedBlockingQueue<Item> queue = new LinkedBlockingQueue<>();
    private final AtomicLong queuedBytes = new AtomicLong();
    private final Map<StreamRef, AtomicLong> lostSinceQueued = new ConcurrentHashMap<>();
    private final Thread worker;
    private volatile boolean closing;

    private final LongAdder messages = new LongAdder();
    private final LongAdder decodeProblems = new LongAdder();
    private final LongAdder unframedBytes = new LongAdder();
    private final LongAdder droppedBytes = new LongAdder();
    private final LongAdder internalErrors = new LongAdder();

    // owned by the worker thread
    private final Map<StreamRef, Framing> framings = new HashMap<>();
    private SpyRecorder recorder;
    private volatile String recorderError;
    private long lastFlushNanos = System.nanoTime();

    /**
     * @param recorder       the spy log, or null to record nothing
     * @param maxQueuedBytes how many forwarded bytes may wait for observation before chunks are dropped
     */
    public ObservationPipeline(StreamBus bus, PlayerDecoder decoder, SpyRecorder recorder, long maxQueuedBytes) {
        this.bus = bus;
        this.decoder = decoder;
        this.recorder = recorder;
        this.maxQueuedBytes = maxQueuedBytes;
        this.worker = Thread.ofPlatform().daemon().name("stagecraft-spy-observer").start(this::work);
    }

    // ---- called on forwarding threads: enqueue only ---------------------------------------------

    @Override
    public void opened(ConnectionInfo connection, long timeNanos) {
        queue.add(new Opened(connection, timeNanos));
    }

    @Override
    public void chunk(ConnectionInfo connection, Direction dir, byte[] data, long timeNanos) {
        AtomicLong lost = lostSinceQueued.computeIfAbsent(new StreamRef(connection.id(), dir), k -> new AtomicLong());
        if (closing || queuedBytes.addAndGet(data.length) > maxQueuedBytes) {
            queuedBytes.addAndGet(-data.length);
            lost.addAndGet(data.length);
            droppedBytes.add(data.length);
            return;
        }
        // One forwarding thread per direction, so the lost count belongs exactly before this chunk.
        queue.add(new Chunk(connection, dir, data, timeNanos, lost.getAndSet(0)));
    }

    /** Recorded in the log and published as a {@link SpyDiagnostic} of the server-to-client stream, at offset 0. */
    @Override
    public void notice(SpyNotice notice, long timeNanos) {
        queue.add(new Noticed(notice.connection(), notice, timeNanos));
    }

    @Override
    public void closed(ConnectionInfo connection, long timeNanos, String reason) {
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

    /** Forwarded bytes that observation had to skip because it fell behind. */
    public long droppedBytes() {
        return droppedBytes.sum();
    }

    public long internalErrors() {
        return internalErrors.sum();
    }

    /** Why the spy log stopped, or null while it is fine (or there is none). */
    public String recorderError() {
        return recorderError;
    }

    /** Processes everything queued so far, then stops and closes the recorder. */
    @Override
    public void close() throws InterruptedException {
        closing = true;
        queue.add(new Closed(null, 0, null)); // wakes the worker; a null connection means "stop"
        worker.join();
    }

    // ---- the observation thread ------------------------------------------------------------------

    private void work() {
        try {
            while (true) {
                Item item = queue.poll(1, TimeUnit.SECONDS);
                if (item != null && item.connection() == null) {
                    break;
                }
                if (item != null) {
                    try {
                        handle(item);
                    } catch (RuntimeException e) {
                        internalErrors.increment(); // a bug here must not stop observing the rest
                    }
                }
                if (System.nanoTime() - lastFlushNanos > 1_000_000_000L) {
                    lastFlushNanos = System.nanoTime();
                    record(r -> r.flush());
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        // Connections still open when observation stops: report what they left unfinished.
        long now = System.currentTimeMillis() * 1_000_000L;
        for (Framing f : framings.values()) {
            f.framer().end();
            drain(f, f.connection(), f.dir(), now);
        }
        framings.values().stream().map(Framing::connection).distinct()
                .forEach(c -> record(r -> r.closed(c, now, "observation stopped")));
        framings.clear();
        record(SpyRecorder::close);
        recorder = null;
    }

    /** A stream's framer and the events it produced for the chunk being handled. */
    private record Framing(ConnectionInfo connection, Direction dir, PlayerFramer framer, List<WireEvent> out) {
        static Framing of(ConnectionInfo connection, Direction dir) {
            List<WireEvent> out = new ArrayList<>(4);
            return new Framing(connection, dir, new PlayerFramer(dir, out::add), out);
        }
    }

    private void handle(Item item) {
        switch (item) {
            case Opened o -> record(r -> r.opened(o.connection(), o.t()));
            case Chunk c -> {
                queuedBytes.addAndGet(-c.data().length);
                Framing f = framings.computeIfAbsent(new StreamRef(c.connection().id(), c.dir()), k -> Framing.of(c.connection(), c.dir()));
                if (c.lostBefore() > 0) {
                    long at = f.framer().nextOffset();
                    f.framer().gap(c.lostBefore(), c.lostBefore() + " bytes were forwarded while the observer was behind");
                    drain(f, c.connection(), c.dir(), c.t());
                    diagnostic(c.connection(), c.dir(), at, c.lostBefore()
                            + " forwarded bytes were not observed (observer queue full)", c.t());
                }
                f.framer().accept(c.data());
                drain(f, c.connection(), c.dir(), c.t());
            }
            case Noticed n -> diagnostic(n.connection(), Direction.SERVER_TO_CLIENT, 0, n.notice().text(), n.t());
            case Closed cl -> {
                for (Direction d : Direction.values()) {
                    StreamRef ref = new StreamRef(cl.connection().id(), d);
                    Framing f = framings.remove(ref);
                    AtomicLong lost = lostSinceQueued.remove(ref);
                    long lostAtEnd = lost == null ? 0 : lost.get();
                    if (f == null && lostAtEnd > 0) {
                        f = Framing.of(cl.connection(), d);
                    }
                    if (f != null) {
                        long at = f.framer().nextOffset();
                        f.framer().gap(lostAtEnd, "the last " + lostAtEnd + " bytes were forwarded while the observer was behind");
                        f.framer().end();
                        drain(f, cl.connection(), d, cl.t());
                        if (lostAtEnd > 0) {
                            diagnostic(cl.connection(), d, at, lostAtEnd
                                    + " forwarded bytes were not observed (observer queue full)", cl.t());
                        }
                    }
                }
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
                        0, 0, null, s.description())));
                bus.publish(new StreamMessage(HoldStreams.STATE, h.t(), s));
            }
        }
    }

    private void drain(Framing f, ConnectionInfo c, Direction dir, long t) {
        for (WireEvent e : f.out()) {
            event(c, dir, e, t);
        }
        f.out().clear();
    }

    private void event(ConnectionInfo c, Direction dir, WireEvent e, long t) {
        record(r -> r.wire(c, dir, e, t));
        switch (e) {
            case WireEvent.Banner b -> {
                // the ident is in the log; tools see the connection through its messages
            }
            case WireEvent.Frame f -> {
                DecodedMessage m = decoder.decode(f);
                messages.increment();
                MessageHeader h = f.header();
                bus.publish(new StreamMessage(SpyStreams.messageKey(c, dir, h), t,
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

    private void record(RecorderCall call) {
        if (recorder == null) {
            return;
        }
        try {
            call.apply(recorder);
        } catch (IOException | RuntimeException e) {
            recorderError = "spy log stopped: " + e.getMessage();
            try {
                recorder.close();
            } catch (IOException | RuntimeException ignored) {
                // already failing; the first error is the one reported
            }
            recorder = null;
        }
    }
}
