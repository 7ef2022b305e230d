package org.stagecraft.spy.breakpoint;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A robot data breakpoint that held on a message from Player. The message (and everything after it on
 * its connection) waits in the spy until {@link #passOn} — the IDE calls it once the program is suspended,
 * so that the program's next read returns exactly this message — or until the bound
 * ({@link DataBreakpoints#passOnBound()}) when nobody does (no debugger).
 */
public final class BreakpointHit {
    private final DataBreakpoint breakpoint;
    private final ConnectionInfo connection;
    private final long offset;
    private final MessageHeader header;
    private final byte[] message;
    private final String why;
    private final List<String> decidingFields;
    private final long timeNanos;
    private final long foundNanos;
    private final boolean disabledByHitCount;
    private final CountDownLatch passed = new CountDownLatch(1);
    private volatile @Nullable String passedOnWhy;
    private volatile long passedOnNanos;

    BreakpointHit(DataBreakpoint breakpoint, ConnectionInfo connection, long offset, MessageHeader header, byte[] message,
            String why, List<String> decidingFields, long timeNanos, long foundNanos, boolean disabledByHitCount) {
        this.breakpoint = breakpoint;
        this.connection = connection;
        this.offset = offset;
        this.header = header;
        this.message = message;
        this.why = why;
        this.decidingFields = List.copyOf(decidingFields);
        this.timeNanos = timeNanos;
        this.foundNanos = foundNanos;
        this.disabledByHitCount = disabledByHitCount;
    }

    public DataBreakpoint breakpoint() {
        return breakpoint;
    }

    public ConnectionInfo connection() {
        return connection;
    }

    /** Where the triggering message starts in the Player-to-program stream (the offset the program sees). */
    public long offset() {
        return offset;
    }

    public MessageHeader header() {
        return header;
    }

    /** The triggering message, header and payload, exactly as Player sent it. */
    public byte[] message() {
        return message.clone();
    }

    /** Why it stopped, for the Debug view and the console: the condition's values, e.g. "min(ranges) = 0.287 m < 0.3 m". */
    public String why() {
        return why;
    }

    /** The triggering message's fields that decided it, as paths ({@code ranges[147]}): what the Robot View marks. */
    public List<String> decidingFields() {
        return decidingFields;
    }

    /** "robot data breakpoint: laser:0 min(ranges) = 0.287 m < 0.3 m" */
    public String description() {
        return "robot data breakpoint: " + breakpoint.text() + " (" + why + ")";
    }

    /** When the message was found, on the spy log's clock (WallClock). */
    public long timeNanos() {
        return timeNanos;
    }

    /** When the message was found, System.nanoTime(): for latencies. */
    public long foundNanos() {
        return foundNanos;
    }

    /** Whether this was the breakpoint's Nth hit and it disabled itself. */
    public boolean disabledByHitCount() {
        return disabledByHitCount;
    }

    /** Lets the held-back messages go on to the program now; later calls do nothing. */
    public void passOn(String reason) {
        if (passedOnWhy == null) {
            synchronized (this) {
                if (passedOnWhy == null) {
                    passedOnWhy = reason;
                    passedOnNanos = System.nanoTime();
                }
            }
        }
        passed.countDown();
    }

    /** Whether the messages went on (or may go on now). */
    public boolean passedOn() {
        return passed.getCount() == 0;
    }

    /** Why the messages went on, or null while they wait. */
    public @Nullable String passedOnWhy() {
        return passedOnWhy;
    }

    /** How long the messages were held back, once passed on. */
    public long heldNanos() {
        long p = passedOnNanos;
        return p == 0 ? 0 : p - foundNanos;
    }

    /** Waits until {@link #passOn} or {@code boundNanos} after the hit, then passes on. */
    void awaitPassOn(long boundNanos, String whenBound) throws InterruptedException {
        long left = boundNanos - (System.nanoTime() - foundNanos);
        if (left > 0 && passed.await(left, TimeUnit.NANOSECONDS)) {
            return;
        }
        passOn(whenBound);
    }

    @Override
    public String toString() {
        return description() + " on connection " + connection.id() + " at offset " + offset;
    }
}
