package org.stagecraft.spy.hold;

import java.io.IOException;
import java.io.OutputStream;
import java.time.Duration;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.LongSupplier;
import java.util.stream.Collectors;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A spy's robot hold: the debugger-safe robot (docs/debugging-robots.md). While held, every connection
 * made while holds were enabled gets zero-velocity commands injected for the position2d devices it
 * has commanded, and the program's motion commands are held back; requests and everything else pass.
 *
 * <p>Holds are off by default and then cost nothing: the relay stays the plain byte copy. Enabling them
 * ({@link #setEnabled}) makes connections accepted from then on message-aware (they follow message
 * boundaries, see {@link HoldingForwarder}); a connection accepted while holds were off cannot be held,
 * because the relay does not know where its messages begin.
 *
 * <p>Reasons are counted ({@link #hold}/{@link #release}): the robots are held while any reason is held
 * at least once. Thread-safe; {@link #hold} and {@link #release} act before they return (the zero
 * commands of connections that are between messages have been written when hold returns).
 */
public final class RobotHold implements AutoCloseable {
    private final HoldObserver observer;
    private final LongSupplier nanoTime;
    private final List<HoldingForwarder> forwarders = new CopyOnWriteArrayList<>();
    private final List<HoldListener> listeners = new CopyOnWriteArrayList<>();

    // guarded by this
    private final EnumMap<HoldReason, Integer> counts = new EnumMap<>(HoldReason.class);
    private boolean enabled;
    private long epoch;
    private long watchdogMillis;
    private @Nullable SilenceWatchdog watchdog;
    private volatile boolean held;
    private volatile long currentEpoch;
    private volatile String reasonsText = "";

    /** Serialises the reporting of changes, so everyone sees them in the order they happened. */
    private final Object reportLock = new Object();
    private HoldState reported;

    public RobotHold(HoldObserver observer) {
        this(observer, System::nanoTime);
    }

    /** @param nanoTime the watchdog's clock (tests pass their own) */
    public RobotHold(HoldObserver observer, LongSupplier nanoTime) {
        this.observer = observer;
        this.nanoTime = nanoTime;
        this.reported = state();
    }

    // ---- the API for launches and UIs ------------------------------------------------------------

    /** Allows holds for connections accepted from now on (off: the byte-exact fast path). */
    public void setEnabled(boolean on) {
        synchronized (this) {
            if (enabled == on) {
                return;
            }
            enabled = on;
            update();
        }
        changed();
    }

    public synchronized boolean isEnabled() {
        return enabled;
    }

    /** Holds the robots for {@code reason} (once more if it already holds). */
    public void hold(HoldReason reason) {
        synchronized (this) {
            counts.merge(reason, 1, Integer::sum);
            update();
        }
        changed();
    }

    /**
     * Takes back one {@link #hold} for {@code reason}.
     *
     * @return false if the reason did not hold (nothing changes)
     */
    public boolean release(HoldReason reason) {
        synchronized (this) {
            @Nullable Integer n = counts.get(reason);
            if (n == null) {
                return false;
            }
            if (n == 1) {
                counts.remove(reason);
            } else {
                counts.put(reason, n - 1);
            }
            update();
        }
        changed();
        return true;
    }

    /** Ends every hold for {@code reason}, however many times it was taken (e.g. the user's "release"). */
    public void releaseAll(HoldReason reason) {
        synchronized (this) {
            if (counts.remove(reason) == null) {
                return;
            }
            update();
        }
        changed();
    }

    /** Whether the robots are held now (enabled and some reason holds). */
    public boolean isHeld() {
        return held;
    }

    public synchronized HoldState state() {
        return new HoldState(enabled, held, counts, watchdogMillis, epoch);
    }

    /** One line for a status bar: what is held and why. */
    public String description() {
        return state().description();
    }

    public void addListener(HoldListener l) {
        listeners.add(l);
    }

    public void removeListener(HoldListener l) {
        listeners.remove(l);
    }

    /**
     * The silence watchdog: when a connection's program has sent nothing for {@code timeout} while its
     * last motion command asked its robot to move, hold (reason {@link HoldReason#WATCHDOG}) until that
     * program sends again. Null or zero turns it off. Needs holds enabled to act.
     */
    public void setWatchdog(@Nullable Duration timeout) {
        SilenceWatchdog stop = null;
        synchronized (this) {
            long ms = timeout == null ? 0 : Math.max(0, timeout.toMillis());
            if (ms == watchdogMillis) {
                return;
            }
            watchdogMillis = ms;
            stop = watchdog;
            watchdog = ms > 0 ? new SilenceWatchdog(this, ms * 1_000_000L) : null;
        }
        if (stop != null) {
            stop.close();
        }
        changed();
    }

    public synchronized Duration watchdog() {
        return Duration.ofMillis(watchdogMillis);
    }

    /** Stops the watchdog thread. */
    @Override
    public void close() {
        SilenceWatchdog w;
        synchronized (this) {
            w = watchdog;
            watchdog = null;
        }
        if (w != null) {
            w.close();
        }
    }

    // ---- for the relay -------------------------------------------------------------------------------

    /**
     * A message-aware forwarder for a new connection's program-to-Player direction, writing to
     * {@code upstream}; null when holds are off (then the relay copies bytes as always).
     */
    public @Nullable HoldingForwarder attach(ConnectionInfo connection, OutputStream upstream) {
        if (!isEnabled()) {
            return null;
        }
        HoldingForwarder f = new HoldingForwarder(this, connection, upstream, observer);
        forwarders.add(f);
        return f;
    }

    /** The connection ended. */
    public void detach(@Nullable HoldingForwarder f) {
        if (f != null && forwarders.remove(f)) {
            f.detached();
        }
    }

    /** The connections that can be held now. */
    public List<HoldingForwarder> forwarders() {
        return List.copyOf(forwarders);
    }

    long epoch() {
        return currentEpoch;
    }

    long nanoTime() {
        return nanoTime.getAsLong();
    }

    String reasonsText() {
        return reasonsText;
    }

    /** One watchdog round at {@code nowNanos} (the watchdog thread calls this; tests may too). */
    public void watchdogCheck(long nowNanos) {
        long timeout;
        synchronized (this) {
            timeout = watchdogMillis * 1_000_000L;
        }
        if (timeout > 0) {
            for (HoldingForwarder f : forwarders) {
                f.watch(nowNanos, timeout);
            }
        }
    }

    // ---- changes ---------------------------------------------------------------------------------

    private void update() { // holding this
        boolean now = enabled && !counts.isEmpty();
        if (now && !held) {
            epoch++;
        }
        currentEpoch = epoch;
        reasonsText = counts.keySet().stream().map(HoldReason::text).collect(Collectors.joining(", "));
        held = now;
    }

    /**
     * Lets the connections act on the current state, then reports it. Each report reads the state
     * afresh, so racing changes end with everyone at the latest state.
     */
    private void changed() {
        synchronized (reportLock) {
            HoldState s = state();
            if (s.equals(reported)) {
                return;
            }
            reported = s;
            for (HoldingForwarder f : forwarders) {
                try {
                    f.holdChanged();
                } catch (IOException e) {
                    // that connection's upstream failed; its relay thread sees the failure and ends it
                }
            }
            try {
                observer.state(s);
            } catch (RuntimeException e) {
                // the log and the bus are observers: they must not stop the hold
            }
            for (HoldListener l : listeners) {
                try {
                    l.holdChanged(s);
                } catch (RuntimeException e) {
                    // a UI's bug must not stop the hold
                }
            }
        }
    }

    /** For tests and status: how many holds each reason has. */
    public synchronized Map<HoldReason, Integer> reasons() {
        return Map.copyOf(counts);
    }

    @Override
    public String toString() {
        return description() + " — " + forwarders.stream().map(f -> "connection " + f.connection().id()).toList();
    }
}
