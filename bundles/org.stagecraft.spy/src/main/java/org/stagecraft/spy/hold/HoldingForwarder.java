package org.stagecraft.spy.hold;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * The program-to-Player direction of one connection when holds are enabled: forwards the program's
 * bytes as they come, but knows where each message begins and ends ({@link BoundaryTracker}), so a
 * hold can act on whole messages only.
 *
 * <ul>
 * <li>Not held: every byte is forwarded at once, in the read's own chunk (one write per read, as
 * the plain relay).</li>
 * <li>Hold begins: as soon as the stream is on a boundary — at once if the program is between
 * messages, else right after the message it is sending — one zero-velocity CMD_VEL is injected for
 * every position2d device this connection has commanded, addressed like its last command there.</li>
 * <li>Held: a message's 40-byte header is kept until it is complete; a position2d command is then held
 * back whole, anything else (requests, data subscriptions, other commands) is forwarded. A device
 * commanded for the first time during the hold gets its zero command right after.</li>
 * <li>Release: nothing is replayed; a header kept back is forwarded, the program's next command takes
 * effect.</li>
 * </ul>
 *
 * Every injected and held-back message is reported to the {@link HoldObserver} with its offsets in
 * both streams. One lock serialises the relay thread and the thread that changes the hold, so an
 * injection can never land inside a message.
 */
public final class HoldingForwarder {
    private record Last(MessageHeader header, int velState) {
    }

    private final RobotHold holds;
    private final ConnectionInfo connection;
    private final SpanWriter upstream;
    private final HoldObserver observer;
    private final Object lock = new Object();

    // guarded by lock
    private final BoundaryTracker tracker = new BoundaryTracker();
    /** The current message's header is being kept back until it is complete (a hold was on at its start). */
    private boolean headerKept;
    private boolean currentHeld;
    private boolean currentMotion;
    private final ByteArrayOutputStream heldBytes = new ByteArrayOutputStream();
    private final ByteArrayOutputStream motionPayload = new ByteArrayOutputStream();
    private long heldUpstreamAt;
    /** Devices this connection has sent motion commands to, in first-command order. */
    private final Map<MotionCommand.Device, Last> devices = new LinkedHashMap<>();
    /** Devices that have had their zero command in the hold of epoch {@link #zeroedEpoch}. */
    private final Set<MotionCommand.Device> zeroed = new HashSet<>();
    private long zeroedEpoch = -1;
    private long injected;
    private long heldBack;

    // the silence watchdog
    private volatile long lastHeardNanos;
    private volatile boolean moving;
    private final AtomicBoolean watchdogHolding = new AtomicBoolean();

    HoldingForwarder(RobotHold holds, ConnectionInfo connection, OutputStream upstream, HoldObserver observer) {
        this.holds = holds;
        this.connection = connection;
        this.upstream = new SpanWriter(upstream);
        this.observer = observer;
        this.lastHeardNanos = holds.nanoTime();
    }

    public ConnectionInfo connection() {
        return connection;
    }

    /** Relays one chunk the program sent (called on the connection's relay thread). */
    public void relay(byte[] buf, int off, int len) throws IOException {
        heard();
        synchronized (lock) {
            int pos = off;
            int end = off + len;
            upstream.begin(buf, off);
            try {
                while (pos < end) {
                    if (tracker.atBoundary()) {
                        // a hold that began since the last boundary has its zero commands sent first
                        injectDue();
                        // a message begins: while held, keep its header until it says what it is
                        headerKept = holds.isHeld();
                    }
                    BoundaryTracker.Part part = tracker.part();
                    int n = tracker.span(end - pos);
                    if (part == BoundaryTracker.Part.HEADER && headerKept) {
                        upstream.flush(); // the tracker keeps the bytes
                    } else if (part == BoundaryTracker.Part.PAYLOAD && currentHeld) {
                        upstream.flush();
                        heldBytes.write(buf, pos, n);
                    } else {
                        upstream.later(pos, n);
                    }
                    if (part == BoundaryTracker.Part.PAYLOAD && currentMotion) {
                        motionPayload.write(buf, pos, n);
                    }
                    int events = tracker.advance(buf, pos, n);
                    pos += n;
                    if ((events & BoundaryTracker.LOST) != 0) {
                        lost();
                    }
                    if ((events & BoundaryTracker.HEADER_DONE) != 0) {
                        headerDone();
                    }
                    if ((events & BoundaryTracker.MESSAGE_DONE) != 0) {
                        messageDone();
                    }
                }
                upstream.flush();
            } finally {
                upstream.end();
            }
        }
    }

    /**
     * The program closed its side: a header still kept back goes on (it was not known to be a motion
     * command, and a direct connection would have delivered it); a held command cut off is reported.
     */
    public void end() throws IOException {
        synchronized (lock) {
            if (headerKept && tracker.headerFill() > 0) {
                headerKept = false;
                write(tracker.headerBytes());
            }
            if (currentHeld) {
                currentHeld = false;
                reportHeld();
            }
        }
    }

    /** The hold changed: inject now if the stream is between messages; on release, let a kept header go. */
    void holdChanged() throws IOException {
        synchronized (lock) {
            if (holds.isHeld()) {
                injectDue();
            } else if (headerKept) {
                headerKept = false;
                if (tracker.headerFill() > 0) {
                    write(tracker.headerBytes());
                }
            }
        }
    }

    // ---- status -----------------------------------------------------------------------------------

    /** Zero commands injected on this connection so far. */
    public long injected() {
        synchronized (lock) {
            return injected;
        }
    }

    /** Program messages held back on this connection so far. */
    public long heldBack() {
        synchronized (lock) {
            return heldBack;
        }
    }

    /** Why this connection's stream cannot be held (it is not Player messages), or null. */
    public @Nullable String problem() {
        synchronized (lock) {
            return tracker.lostReason();
        }
    }

    /** Whether the program's last motion command asked its robot to move. */
    public boolean moving() {
        return moving;
    }

    // ---- the silence watchdog ---------------------------------------------------------------------

    private void heard() {
        lastHeardNanos = holds.nanoTime();
        if (watchdogHolding.compareAndSet(true, false)) {
            holds.release(HoldReason.WATCHDOG); // before its bytes: what it sends now takes effect
        }
    }

    /** Holds (reason WATCHDOG) if the program has been silent for {@code timeoutNanos} while moving. */
    void watch(long nowNanos, long timeoutNanos) {
        long seen = lastHeardNanos;
        if (moving && nowNanos - seen >= timeoutNanos && watchdogHolding.compareAndSet(false, true)) {
            if (lastHeardNanos != seen && watchdogHolding.compareAndSet(true, false)) {
                return; // it spoke in the meantime
            }
            holds.hold(HoldReason.WATCHDOG);
        }
    }

    /** The connection ended: a watchdog hold on its account ends with it. */
    void detached() {
        if (watchdogHolding.getAndSet(false)) {
            holds.release(HoldReason.WATCHDOG);
        }
    }

    // ---- message by message -----------------------------------------------------------------------

    private void headerDone() throws IOException {
        currentMotion = MotionCommand.isMotion(tracker.interf(), tracker.type());
        motionPayload.reset();
        if (headerKept) {
            headerKept = false;
            byte[] header = tracker.headerBytes();
            if (currentMotion && holds.isHeld()) {
                currentHeld = true;
                heldBytes.reset();
                heldBytes.write(header);
                upstream.flush();
                heldUpstreamAt = upstream.written();
            } else {
                write(header);
            }
        }
    }

    private void messageDone() throws IOException {
        if (currentMotion) {
            MessageHeader h = tracker.header();
            byte[] payload = motionPayload.toByteArray();
            MotionCommand.Device d = MotionCommand.Device.of(h);
            int state = MotionCommand.velState(h, payload);
            @Nullable Last before = devices.get(d);
            devices.put(d, new Last(h, state >= 0 ? state : before != null ? before.velState() : -1));
            moving = MotionCommand.moving(h, payload);
        }
        if (currentHeld) {
            currentHeld = false;
            reportHeld();
        }
        currentMotion = false;
        injectDue();
    }

    private void lost() throws IOException {
        if (headerKept) {
            headerKept = false; // not a message header: nothing to decide, it goes on like everything after it
            write(tracker.headerBytes());
        }
    }

    private void reportHeld() {
        heldBack++;
        byte[] bytes = heldBytes.toByteArray();
        heldBytes.reset();
        MessageHeader h = tracker.header();
        observer.action(new HoldAction(connection, HoldEntry.Action.HELD_BACK, tracker.messageStart(), heldUpstreamAt, h,
                bytes, "held back " + commandName(h) + " to " + MotionCommand.Device.of(h) + " (" + holds.reasonsText() + ")"));
    }

    /** On a boundary while held: a zero command for every device not yet zeroed in this hold. */
    private void injectDue() throws IOException {
        if (!holds.isHeld() || !tracker.atBoundary()) {
            return;
        }
        long epoch = holds.epoch();
        if (epoch != zeroedEpoch) {
            zeroed.clear();
            zeroedEpoch = epoch;
        }
        for (Map.Entry<MotionCommand.Device, Last> e : devices.entrySet()) {
            if (!zeroed.add(e.getKey())) {
                continue;
            }
            Last last = e.getValue();
            byte[] msg = ZeroVelocity.command(last.header(), last.velState() >= 0 ? last.velState() : 1);
            upstream.flush(); // the bytes before it first: its upstream offset is where it really lands
            long at = upstream.written();
            write(msg);
            injected++;
            observer.action(new HoldAction(connection, HoldEntry.Action.INJECTED, tracker.offset(), at,
                    MessageHeader.read(msg, 0), msg, "zero velocity to " + e.getKey() + " (" + holds.reasonsText() + ")"));
        }
    }

    private static String commandName(MessageHeader h) {
        return switch (h.subtype()) {
            case MotionCommand.CMD_VEL -> "CMD_VEL";
            case MotionCommand.CMD_POS -> "CMD_POS";
            case MotionCommand.CMD_CAR -> "CMD_CAR";
            case MotionCommand.CMD_VEL_HEAD -> "CMD_VEL_HEAD";
            default -> "command " + h.subtype();
        };
    }

    private void write(byte[] b) throws IOException {
        upstream.write(b);
    }
}
