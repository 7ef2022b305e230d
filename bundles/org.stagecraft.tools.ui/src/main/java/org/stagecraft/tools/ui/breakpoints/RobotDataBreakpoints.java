package org.stagecraft.tools.ui.breakpoints;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.core.resources.IMarkerDelta;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.debug.core.IBreakpointListener;
import org.eclipse.debug.core.IBreakpointManager;
import org.eclipse.debug.core.IBreakpointManagerListener;
import org.eclipse.debug.core.model.IBreakpoint;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.spy.breakpoint.BreakpointHit;

/**
 * The one registry of robot data breakpoints in the workbench: follows the platform's breakpoint manager
 * (added, removed, changed, "Skip All Breakpoints") and gives every running session's spy the current
 * list; writes what a hit found back to its breakpoint (its last hit, and disabled when its hit count was
 * reached).
 */
public final class RobotDataBreakpoints implements IBreakpointListener, IBreakpointManagerListener {
    private static final RobotDataBreakpoints INSTANCE = new RobotDataBreakpoints();

    private final List<SessionDataBreakpoints> sessions = new CopyOnWriteArrayList<>();
    private boolean listening;

    private RobotDataBreakpoints() {
    }

    public static RobotDataBreakpoints get() {
        return INSTANCE;
    }

    /** The sessions whose spies follow the workbench's robot data breakpoints. */
    public List<SessionDataBreakpoints> sessions() {
        return List.copyOf(sessions);
    }

    /** Every robot data breakpoint of the workspace. */
    public static List<RobotDataBreakpoint> all() {
        return java.util.Arrays.stream(SessionDataBreakpoints.manager().getBreakpoints(RobotDataBreakpoint.MODEL))
                .filter(RobotDataBreakpoint.class::isInstance).map(RobotDataBreakpoint.class::cast).toList();
    }

    synchronized void register(SessionDataBreakpoints s) {
        if (!listening) {
            IBreakpointManager m = SessionDataBreakpoints.manager();
            m.addBreakpointListener(this);
            m.addBreakpointManagerListener(this);
            listening = true;
        }
        sessions.add(s);
        push(s);
    }

    void unregister(SessionDataBreakpoints s) {
        sessions.remove(s);
    }

    /** Ends every session's current hit (the Tools view's Resume Robots). */
    public void resumeAll() {
        for (SessionDataBreakpoints s : sessions) {
            s.resume();
        }
    }

    private void pushAll() {
        for (SessionDataBreakpoints s : sessions) {
            push(s);
        }
    }

    private static void push(SessionDataBreakpoints s) {
        IBreakpointManager m = SessionDataBreakpoints.manager();
        s.update(List.of(m.getBreakpoints(RobotDataBreakpoint.MODEL)), !m.isEnabled());
    }

    /** Writes the hit back to its breakpoint: its last hit, and disabled when its hit count was reached. */
    void hit(BreakpointHit hit) {
        String id = hit.breakpoint().id();
        Job job = Job.create("Robot data breakpoint hit", monitor -> {
            for (RobotDataBreakpoint b : all()) {
                if (SessionDataBreakpoints.id(b).equals(id)) {
                    try {
                        b.setLastHit(hit.why());
                        if (hit.disabledByHitCount()) {
                            b.setEnabled(false);
                        }
                    } catch (CoreException e) {
                        return e.getStatus();
                    }
                }
            }
            return Status.OK_STATUS;
        });
        job.setSystem(true);
        job.schedule();
    }

    @NonNullByDefault({})
    @Override
    public void breakpointAdded(IBreakpoint breakpoint) {
        changed(breakpoint);
    }

    @NonNullByDefault({})
    @Override
    public void breakpointRemoved(IBreakpoint breakpoint, @Nullable IMarkerDelta delta) {
        changed(breakpoint);
    }

    @NonNullByDefault({})
    @Override
    public void breakpointChanged(IBreakpoint breakpoint, @Nullable IMarkerDelta delta) {
        changed(breakpoint);
    }

    private void changed(IBreakpoint b) {
        if (b instanceof RobotDataBreakpoint) {
            pushAll();
        }
    }

    @Override
    public void breakpointManagerEnablementChanged(boolean enabled) {
        pushAll();
    }
}
