package org.stagecraft.tools.ui.launch;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugException;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.IDebugEventSetListener;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.model.IDebugElement;
import org.eclipse.debug.core.model.IDebugTarget;
import org.eclipse.debug.core.model.IThread;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.RobotHold;

/**
 * Holds a session's robots while its robot program is suspended in a debugger: any thread of any debug
 * target of the session's launch, or of a launch linked to it (the PyDev launch of the program), stopped
 * at a breakpoint, after a step, by Suspend or an exception breakpoint. When every such thread runs again
 * (or ends), the hold is released. Works for any Eclipse debug model, PyDev's included, because it only
 * reads the platform's debug events.
 *
 * <p>The whole session takes one {@link HoldReason#SUSPENDED} hold, however many threads are suspended:
 * the robots are held while at least one is. Implicit evaluations (a hover that runs code in the
 * suspended thread) resume and suspend again at once; they are ignored, so the robot does not twitch.
 */
public final class SuspendHold implements IDebugEventSetListener, AutoCloseable {
    private final RobotHold hold;
    private final Supplier<List<ILaunch>> launches;
    /** Suspended threads (or the target itself, for a target that suspends as a whole), per target. */
    private final Map<IDebugTarget, Set<Object>> suspended = new HashMap<>();
    private boolean holding;
    private boolean closed;

    /**
     * @param launches the session's launch and the launches linked to it, asked at each event (links
     *                 are added while the session runs)
     */
    public SuspendHold(RobotHold hold, Supplier<List<ILaunch>> launches) {
        this.hold = hold;
        this.launches = launches;
    }

    /** Starts listening to the platform's debug events. */
    public SuspendHold start() {
        DebugPlugin.getDefault().addDebugEventListener(this);
        return this;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void handleDebugEvents(DebugEvent[] events) {
        List<ILaunch> mine = null;
        for (DebugEvent e : events) {
            if (!(e.getSource() instanceof IDebugElement element) || e.getDetail() == DebugEvent.EVALUATION_IMPLICIT) {
                continue;
            }
            IDebugTarget target = element.getDebugTarget();
            if (target == null) {
                continue;
            }
            if (mine == null) {
                mine = launches.get();
            }
            if (!mine.contains(target.getLaunch())) {
                continue;
            }
            Object who = e.getSource() instanceof IThread t ? t : target;
            switch (e.getKind()) {
                case DebugEvent.SUSPEND -> suspended(target, who);
                // a whole target resuming or ending takes all its threads along
                case DebugEvent.RESUME, DebugEvent.TERMINATE -> resumed(target, who == target ? null : who);
                default -> {
                }
            }
        }
        update();
    }

    /**
     * Catches up with a launch linked after its targets were made: a program launched in debug mode
     * may stop (e.g. "stop at first line") before the link exists, and that event went unheard.
     */
    public void scan(ILaunch launch) {
        for (IDebugTarget target : launch.getDebugTargets()) {
            try {
                for (IThread t : target.getThreads()) {
                    if (t.isSuspended()) {
                        suspended(target, t);
                    }
                }
            } catch (DebugException e) {
                // a target that cannot list its threads has ended or is ending: nothing of it is suspended
            }
            if (target.isSuspended()) {
                suspended(target, target);
            }
        }
        update();
    }

    private synchronized void suspended(IDebugTarget target, Object who) {
        suspended.computeIfAbsent(target, t -> new HashSet<>()).add(who);
    }

    private synchronized void resumed(IDebugTarget target, @Nullable Object who) {
        @Nullable Set<Object> s = suspended.get(target);
        if (s == null) {
            return;
        }
        if (who == null) {
            s.clear();
        } else {
            s.remove(who);
        }
        if (s.isEmpty()) {
            suspended.remove(target);
        }
    }

    /** Takes or gives back the session's one hold when "anything suspended" changed. */
    private synchronized void update() {
        boolean any = !closed && !suspended.isEmpty();
        if (any && !holding) {
            holding = true;
            hold.hold(HoldReason.SUSPENDED);
        } else if (!any && holding) {
            holding = false;
            hold.release(HoldReason.SUSPENDED);
        }
    }

    /** Whether some thread of the session's program is suspended now. */
    public synchronized boolean isHolding() {
        return holding;
    }

    /** Stops listening and releases the hold it took. */
    @Override
    public void close() {
        DebugPlugin.getDefault().removeDebugEventListener(this);
        synchronized (this) {
            closed = true;
            suspended.clear();
        }
        update();
    }
}
