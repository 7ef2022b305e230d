package org.stagecraft.spy.breakpoint;

import java.io.OutputStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldObserver;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.WallClock;

/**
 * A spy's robot data breakpoints (docs/debugging-robots.md). Off by default, and then the relay's
 * Player-to-program direction is the plain byte copy. Enabled ({@link #setEnabled}), connections accepted
 * from then on follow their message boundaries ({@link BreakpointGate}), so a breakpoint set at any time
 * can act on them; with no breakpoint set nothing is kept or held back.
 *
 * <p>When a message from Player satisfies an enabled breakpoint: the robots are held (reason
 * {@link HoldReason#DATA_BREAKPOINT}), the hit is logged and given to the listeners, and the message and
 * everything after it on that connection wait until {@link BreakpointHit#passOn} or the bound. One hit is
 * open at a time: until {@link #resume()}, no breakpoint is tested (the program is being looked at).
 * Thread-safe.
 */
public final class DataBreakpoints implements AutoCloseable {
    /** How long the messages wait for someone to suspend the program when nobody passes them on. */
    public static final Duration DEFAULT_PASS_ON_BOUND = Duration.ofSeconds(2);

    private final RobotHold holds;
    private final HoldObserver observer;
    private final List<BreakpointListener> listeners = new CopyOnWriteArrayList<>();

    // guarded by this
    private boolean enabled;
    private final List<DataBreakpoint> breakpoints = new ArrayList<>();
    private final Map<String, Integer> counts = new HashMap<>();
    private @Nullable BreakpointHit open;
    /** Breakpoints resumed while their condition still held, in {@link #untilFalse} mode: not tested until it stops holding. */
    private final java.util.Set<String> latched = new java.util.HashSet<>();
    private boolean untilFalse;
    private volatile boolean armed;
    private volatile Duration passOnBound = DEFAULT_PASS_ON_BOUND;

    public DataBreakpoints(RobotHold holds, HoldObserver observer) {
        this.holds = holds;
        this.observer = observer;
    }

    /** Makes connections accepted from now on able to stop at breakpoints. */
    public synchronized void setEnabled(boolean on) {
        enabled = on;
        rearm();
    }

    public synchronized boolean isEnabled() {
        return enabled;
    }

    /** Replaces every breakpoint (an IDE passes its Breakpoints view's list). Hit counts start again for new ids. */
    public synchronized void set(List<DataBreakpoint> all) {
        breakpoints.clear();
        breakpoints.addAll(all);
        counts.keySet().retainAll(all.stream().map(DataBreakpoint::id).toList());
        rearm();
    }

    public synchronized void add(DataBreakpoint b) {
        breakpoints.removeIf(x -> x.id().equals(b.id()));
        breakpoints.add(b);
        rearm();
    }

    public synchronized void remove(String id) {
        breakpoints.removeIf(x -> x.id().equals(id));
        counts.remove(id);
        rearm();
    }

    /**
     * After {@link #resume()}, whether the breakpoint that stopped stops again only once its condition has
     * stopped holding for a message (off: it stops at the next message that satisfies it, as Eclipse's
     * breakpoints do). The command line turns it on: without a debugger to disable the breakpoint, a robot
     * held at "nearer than 0.3 m" could otherwise never drive away.
     */
    public synchronized void untilFalse(boolean on) {
        untilFalse = on;
        if (!on) {
            latched.clear();
        }
    }

    public synchronized List<DataBreakpoint> breakpoints() {
        return List.copyOf(breakpoints);
    }

    /** How long a hit's messages wait for {@link BreakpointHit#passOn} before they go on anyway. */
    public void passOnBound(Duration bound) {
        if (bound.isNegative()) {
            throw new IllegalArgumentException("the pass-on bound cannot be negative: " + bound);
        }
        passOnBound = bound;
    }

    public Duration passOnBound() {
        return passOnBound;
    }

    public void addListener(BreakpointListener l) {
        listeners.add(l);
    }

    public void removeListener(BreakpointListener l) {
        listeners.remove(l);
    }

    /** The hit being looked at (until {@link #resume()}), or null. */
    public synchronized @Nullable BreakpointHit current() {
        return open;
    }

    /**
     * Ends the open hit: its messages go on if they still wait, the robots' hold for it ends, and
     * breakpoints are tested again. Does nothing without an open hit.
     */
    public void resume() {
        BreakpointHit h;
        synchronized (this) {
            h = open;
            if (h == null) {
                return;
            }
            open = null;
            if (untilFalse) {
                latched.add(h.breakpoint().id());
            }
            rearm();
        }
        h.passOn("resumed");
        holds.release(HoldReason.DATA_BREAKPOINT);
        for (BreakpointListener l : listeners) {
            try {
                l.resumed(h);
            } catch (RuntimeException e) {
                // a listener's bug must not keep the robots held
            }
        }
    }

    /** Passes on a waiting hit's messages (the spy is stopping). */
    @Override
    public void close() {
        BreakpointHit h = current();
        if (h != null) {
            h.passOn("the spy stopped");
        }
    }

    // ---- for the relay ------------------------------------------------------------------------------

    /** The gate for a new connection's Player-to-program direction, or null when breakpoints are off. */
    public @Nullable BreakpointGate attach(ConnectionInfo connection, OutputStream downstream) {
        return isEnabled() ? new BreakpointGate(this, connection, downstream) : null;
    }

    /** Whether messages must be tested now (some breakpoint enabled, no hit open). */
    boolean armed() {
        return armed;
    }

    private void rearm() { // holding this
        armed = enabled && open == null && breakpoints.stream().anyMatch(DataBreakpoint::enabled);
    }

    synchronized boolean watches(ConnectionInfo c, MessageHeader h) {
        if (!armed) {
            return false;
        }
        for (DataBreakpoint b : breakpoints) {
            if (b.enabled() && b.condition().watches(c, h)) {
                return true;
            }
        }
        return false;
    }

    /** Tests a whole message; on a hit, holds the robots, logs and tells the listeners. */
    @Nullable BreakpointHit test(ConnectionInfo c, long offset, MessageHeader h, byte[] message) {
        List<DataBreakpoint> candidates;
        synchronized (this) {
            if (!armed) {
                return null;
            }
            candidates = breakpoints.stream().filter(b -> b.enabled() && b.condition().watches(c, h)).toList();
        }
        byte[] payload = java.util.Arrays.copyOfRange(message, MessageHeader.SIZE, message.length);
        for (DataBreakpoint b : candidates) {
            MessageCondition.Satisfied why;
            try {
                why = b.condition().test(h, payload);
            } catch (RuntimeException e) {
                why = null; // a message the condition cannot read does not satisfy it
            }
            if (why == null) {
                synchronized (this) {
                    latched.remove(b.id()); // its condition stopped holding: it may stop again
                }
                continue;
            }
            BreakpointHit hit;
            synchronized (this) {
                if (!armed || !breakpoints.contains(b)) {
                    return null; // another connection's hit came first, or the breakpoint went away
                }
                if (latched.contains(b.id())) {
                    continue; // resumed while it held, and it still holds
                }
                int n = counts.merge(b.id(), 1, Integer::sum);
                if (b.hitCount() > 0 && n != b.hitCount()) {
                    continue; // before its Nth hit; after it, stopped once already (its owner may not have disabled it yet)
                }
                boolean disable = b.hitCount() > 0;
                if (disable) {
                    breakpoints.set(breakpoints.indexOf(b), new DataBreakpoint(b.id(), b.condition(), false, b.hitCount()));
                }
                hit = new BreakpointHit(b, c, offset, h, message, why.why(), why.decidingFields(), WallClock.nowNanos(),
                        System.nanoTime(), disable);
                open = hit;
                rearm();
            }
            // the hit first, then what it did: the log reads BREAK, then the hold's zero commands
            report(new HoldAction(c, HoldEntry.Action.BREAK, offset, offset, h, message, hit.description(),
                    hit.decidingFields()));
            holds.hold(HoldReason.DATA_BREAKPOINT);
            for (BreakpointListener l : listeners) {
                try {
                    l.hit(hit);
                } catch (RuntimeException e) {
                    // a listener's bug must not lose the hit: the bound passes the messages on
                }
            }
            return hit;
        }
        return null;
    }

    /** The gate let a hit's messages go. */
    void passedOn(BreakpointHit hit) {
        String why = hit.passedOnWhy();
        report(new HoldAction(hit.connection(), HoldEntry.Action.PASSED_ON, hit.offset(), hit.offset(), hit.header(),
                new byte[0], String.format(java.util.Locale.ROOT, "messages from Player passed on to the program after %.1f ms: %s",
                        hit.heldNanos() / 1e6, why)));
        for (BreakpointListener l : listeners) {
            try {
                l.passedOn(hit);
            } catch (RuntimeException e) {
                // the wire goes on regardless
            }
        }
    }

    private void report(HoldAction a) {
        try {
            observer.action(a);
        } catch (RuntimeException e) {
            // the log and the bus are observers: they must not stop the breakpoint
        }
    }
}
