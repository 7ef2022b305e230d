package org.stagecraft.tools.ui.launch;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.RobotHold;

/**
 * The user's emergency stop: while engaged, every robot of every running Robot Session is held (reason
 * {@link HoldReason#EMERGENCY_STOP}), sessions started meanwhile included, until the user releases it.
 * One per workbench; the Tools view's and the Robot View's toolbar buttons toggle it.
 *
 * <p>It can only hold what the spies can hold: connections accepted while holds were enabled, which a
 * session does whenever "hold while suspended" or the silence watchdog is on. A session with both off
 * keeps the plain byte copy, and its robots are not stopped; {@link #unholdable()} counts those.
 */
public final class EmergencyStop {
    private static final EmergencyStop INSTANCE = new EmergencyStop();

    private final Set<RobotHold> sessions = new LinkedHashSet<>();
    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    private boolean engaged;

    public static EmergencyStop get() {
        return INSTANCE;
    }

    /** A session started: held at once if the stop is engaged. */
    public void register(RobotHold hold) {
        synchronized (this) {
            if (!sessions.add(hold) || !engaged) {
                return;
            }
            hold.hold(HoldReason.EMERGENCY_STOP);
        }
        changed();
    }

    /** A session ended. */
    public void unregister(RobotHold hold) {
        synchronized (this) {
            if (!sessions.remove(hold)) {
                return;
            }
        }
        changed();
    }

    /** Holds every robot of every running session until {@link #release()}. */
    public void engage() {
        synchronized (this) {
            if (engaged) {
                return;
            }
            engaged = true;
            sessions.forEach(h -> h.hold(HoldReason.EMERGENCY_STOP));
        }
        changed();
    }

    /** Ends the emergency stop everywhere; the programs' next commands take effect (nothing is replayed). */
    public void release() {
        synchronized (this) {
            if (!engaged) {
                return;
            }
            engaged = false;
            sessions.forEach(h -> h.releaseAll(HoldReason.EMERGENCY_STOP));
        }
        changed();
    }

    /** @return whether it is engaged now */
    public boolean toggle() {
        if (isEngaged()) {
            release();
            return false;
        }
        engage();
        return true;
    }

    public synchronized boolean isEngaged() {
        return engaged;
    }

    /** Running sessions whose spy cannot hold (holds off): an emergency stop does not stop their robots. */
    public synchronized int unholdable() {
        return (int) sessions.stream().filter(h -> !h.isEnabled()).count();
    }

    public synchronized int sessions() {
        return sessions.size();
    }

    /** For the button's tooltip: what pressing it does now, and its limit. */
    public synchronized String tooltip() {
        String limit = "Only sessions with 'Hold the robots while the program is suspended' or the silence watchdog on "
                + "can be held";
        int off = unholdable();
        String now = off == 0 ? "" : " (" + off + " running session" + (off == 1 ? " has" : "s have") + " holds off)";
        return engaged
                ? "Emergency stop engaged: robots held (zero velocity, motion commands held back). Press to release. "
                        + limit + now + "."
                : "Emergency stop: hold every robot of every running Robot Session until pressed again. " + limit + now + ".";
    }

    /** Told (on the changing thread) after each change of state or of the sessions. */
    public void addListener(Runnable l) {
        listeners.add(l);
    }

    public void removeListener(Runnable l) {
        listeners.remove(l);
    }

    private void changed() {
        listeners.forEach(Runnable::run);
    }
}
