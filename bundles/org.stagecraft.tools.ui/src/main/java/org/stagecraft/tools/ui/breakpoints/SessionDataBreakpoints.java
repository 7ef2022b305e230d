package org.stagecraft.tools.ui.breakpoints;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.Supplier;

import org.eclipse.core.runtime.CoreException;
import org.eclipse.debug.core.DebugEvent;
import org.eclipse.debug.core.DebugException;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.IBreakpointManager;
import org.eclipse.debug.core.IDebugEventSetListener;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.model.IBreakpoint;
import org.eclipse.debug.core.model.IDebugElement;
import org.eclipse.debug.core.model.IDebugTarget;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.fields.StreamCondition;
import org.stagecraft.spy.breakpoint.BreakpointHit;
import org.stagecraft.spy.breakpoint.BreakpointListener;
import org.stagecraft.spy.breakpoint.DataBreakpoint;
import org.stagecraft.spy.breakpoint.DataBreakpoints;

/**
 * The workbench's robot data breakpoints on one running Robot Session's spy, and what a hit does to its
 * robot program: every debug target of the session's launches is asked to suspend; once one reports SUSPEND,
 * or {@link #suspendSettle} after the request, the triggering message goes on to the program, so its next
 * read returns exactly that message. The settle time is there because a program waiting in a socket read
 * cannot stop before the read returns: a Python debugger (pydevd) stops a thread at its next line of
 * Python, so the message must go on once the request has reached the debugger, and the program stops right
 * after its read, holding the message. The user's Resume ends the hit (the robots move again, breakpoints
 * are tested again). Steps do not end it: the
 * robots stay held while the user steps through how the program handles the message. A program that is
 * not debugged cannot be suspended: the message goes on after the spy's bound, the robots stay held, and
 * the spy's console says so ({@link #resume()} and the Tools view's Resume Robots end it).
 */
public final class SessionDataBreakpoints implements BreakpointListener, IDebugEventSetListener, AutoCloseable {
    private final DataBreakpoints spy;
    private final Supplier<List<ILaunch>> launches;
    private final Consumer<String> say;
    private final Consumer<String> status;
    /** The hit waiting for the program to be suspended, or null. */
    private volatile @Nullable BreakpointHit waiting;
    private volatile @Nullable List<IDebugTarget> suspending;
    private volatile Duration suspendSettle = DEFAULT_SUSPEND_SETTLE;

    /** How long a suspend request is given to reach the program's debugger before the message goes on. */
    public static final Duration DEFAULT_SUSPEND_SETTLE = Duration.ofMillis(250);

    /**
     * @param launches the session's launch and those linked to it, asked at each hit
     * @param say      a line for the session's spy console
     * @param status   why the session stopped its program, for the spy's line in the Debug view ("" when the hit ends)
     */
    public SessionDataBreakpoints(DataBreakpoints spy, Supplier<List<ILaunch>> launches, Consumer<String> say,
            Consumer<String> status) {
        this.spy = spy;
        this.launches = launches;
        this.say = say;
        this.status = status;
    }

    public SessionDataBreakpoints start() {
        spy.addListener(this);
        DebugPlugin.getDefault().addDebugEventListener(this);
        RobotDataBreakpoints.get().register(this);
        return this;
    }

    /** Gives the spy the workbench's enabled robot data breakpoints (none while "Skip All Breakpoints" is on). */
    void update(List<IBreakpoint> all, boolean skipAll) {
        List<DataBreakpoint> out = new ArrayList<>();
        for (IBreakpoint b : all) {
            if (b instanceof RobotDataBreakpoint r && r.getMarker() != null && r.getMarker().exists()) {
                @Nullable StreamCondition c = r.parsed();
                boolean enabled;
                try {
                    enabled = r.isEnabled() && !skipAll;
                } catch (CoreException e) {
                    enabled = false;
                }
                if (c != null) {
                    out.add(new DataBreakpoint(id(r), c, enabled, r.hitCount()));
                }
            }
        }
        spy.set(out);
    }

    static String id(RobotDataBreakpoint b) {
        return Long.toString(b.getMarker().getId());
    }

    /** See {@link #DEFAULT_SUSPEND_SETTLE}; tests set a long one to see the SUSPEND event pass the message on. */
    public void suspendSettle(Duration settle) {
        suspendSettle = settle;
    }

    /** The spy's breakpoints, for tests and the Tools view. */
    public DataBreakpoints spy() {
        return spy;
    }

    /** Ends the current hit (the robots move again), e.g. for a program that is not debugged. */
    public void resume() {
        spy.resume();
    }

    // ---- hits (on the spy's relay thread) -----------------------------------------------------------

    @Override
    public void hit(BreakpointHit hit) {
        List<IDebugTarget> targets = new ArrayList<>();
        for (ILaunch l : launches.get()) {
            for (IDebugTarget t : l.getDebugTargets()) {
                if (!t.isTerminated() && t.canSuspend()) {
                    targets.add(t);
                }
            }
        }
        say.accept(hit.description() + " on connection " + hit.connection().id() + ": robots held"
                + (targets.isEmpty() ? "; the program is not being debugged, so it runs on (Resume Robots in the Tools view releases)"
                        : "; suspending the program"));
        RobotDataBreakpoints.get().hit(hit);
        status.accept("stopped: " + hit.why()); // short: the Debug view is narrow; the condition is in the Breakpoints view
        if (targets.isEmpty()) {
            return; // the spy's bound lets the message go on
        }
        waiting = hit;
        suspending = targets;
        Duration settle = suspendSettle;
        Thread.ofVirtual().name("stagecraft-data-breakpoint-suspend").start(() -> {
            for (IDebugTarget t : targets) {
                try {
                    t.suspend();
                } catch (DebugException e) {
                    say.accept("could not suspend " + t + ": " + e.getMessage());
                }
            }
            try {
                Thread.sleep(settle); // a bound, not a synchronisation: a SUSPEND event passes the message on sooner
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            if (waiting == hit) {
                waiting = null;
                hit.passOn("the program was asked to suspend (it stops at its next line once its read returns)");
            }
        });
    }

    @Override
    public void passedOn(BreakpointHit hit) {
        say.accept(String.format(Locale.ROOT, "the triggering message went on to the program after %.1f ms: %s",
                hit.heldNanos() / 1e6, hit.passedOnWhy()));
    }

    @Override
    public void resumed(BreakpointHit hit) {
        say.accept("robot data breakpoint ended: the robots move again");
        status.accept("");
    }

    // ---- the debugger ------------------------------------------------------------------------------

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void handleDebugEvents(DebugEvent[] events) {
        for (DebugEvent e : events) {
            if (!(e.getSource() instanceof IDebugElement element) || e.getDetail() == DebugEvent.EVALUATION_IMPLICIT) {
                continue;
            }
            IDebugTarget target = element.getDebugTarget();
            if (target == null || !launches.get().contains(target.getLaunch())) {
                continue;
            }
            BreakpointHit w = waiting;
            if (e.getKind() == DebugEvent.SUSPEND && w != null) {
                waiting = null;
                w.passOn("the program was suspended in the debugger");
            } else if (e.getKind() == DebugEvent.TERMINATE
                    || e.getKind() == DebugEvent.RESUME && e.getDetail() == DebugEvent.CLIENT_REQUEST && spy.current() != null) {
                // the user's Resume (not a step) ends the hit; so does the program's end
                waiting = null;
                if (spy.current() != null) {
                    spy.resume();
                }
            }
        }
    }

    @Override
    public void close() {
        DebugPlugin.getDefault().removeDebugEventListener(this);
        spy.removeListener(this);
        RobotDataBreakpoints.get().unregister(this);
        BreakpointHit w = waiting;
        if (w != null) {
            w.passOn("the session ended");
        }
    }

    /** The breakpoint manager this session follows (for the registry). */
    static IBreakpointManager manager() {
        return DebugPlugin.getDefault().getBreakpointManager();
    }
}
