package org.stagecraft.tools.ui.breakpoints;

import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IWorkspaceRoot;
import org.eclipse.core.resources.IWorkspaceRunnable;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.Status;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.model.Breakpoint;
import org.eclipse.debug.core.model.IBreakpoint;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.replay.fields.ConditionException;
import org.stagecraft.replay.fields.StreamCondition;

/**
 * A robot data breakpoint: stop the robot program when what Player sends satisfies a condition, e.g.
 * {@code laser:0 min(ranges) < 0.3} (the field language of {@link StreamCondition}). A platform breakpoint
 * like any other: listed in the Breakpoints view, enabled and disabled there, persisted with the workspace
 * as a marker on the workspace root (it belongs to no file), with a hit count (stop on the Nth hit only,
 * then disable itself).
 */
public final class RobotDataBreakpoint extends Breakpoint {
    /** The debug model robot data breakpoints belong to (no debug target is of it: the spy evaluates them). */
    public static final String MODEL = "org.stagecraft.robot";
    public static final String MARKER = "org.stagecraft.tools.ui.robotDataBreakpointMarker";
    /** Marker attribute: the condition as the user wrote it. */
    public static final String CONDITION = "org.stagecraft.robotData.condition";
    /** Marker attribute: stop on this hit only (0: every hit). */
    public static final String HIT_COUNT = "org.stagecraft.robotData.hitCount";
    /** Marker attribute: why it last stopped, e.g. "laser:0 min(ranges) = 0.287 m < 0.3". */
    public static final String LAST_HIT = "org.stagecraft.robotData.lastHit";

    /** For the platform, which restores breakpoints from their markers. */
    public RobotDataBreakpoint() {
    }

    /**
     * Adds a robot data breakpoint to the workspace's breakpoints.
     *
     * @throws CoreException saying where and why the condition cannot be read
     */
    public static RobotDataBreakpoint create(String condition, int hitCount) throws CoreException {
        String text = check(condition);
        RobotDataBreakpoint b = new RobotDataBreakpoint();
        IWorkspaceRoot root = ResourcesPlugin.getWorkspace().getRoot();
        IWorkspaceRunnable make = monitor -> {
            IMarker m = root.createMarker(MARKER);
            m.setAttributes(new String[] { IBreakpoint.ID, IBreakpoint.ENABLED, IBreakpoint.PERSISTED, CONDITION, HIT_COUNT,
                    IMarker.MESSAGE }, new Object[] { MODEL, Boolean.TRUE, Boolean.TRUE, text, Math.max(0, hitCount),
                            message(text, hitCount) });
            b.setMarker(m);
        };
        ResourcesPlugin.getWorkspace().run(make, null);
        DebugPlugin.getDefault().getBreakpointManager().addBreakpoint(b);
        return b;
    }

    /** The condition, stripped, if it can be read; else a CoreException with its position and reason. */
    static String check(String condition) throws CoreException {
        @Nullable String problem = problem(condition);
        if (problem != null) {
            throw new CoreException(Status.error("robot data breakpoint '" + condition + "': " + problem));
        }
        return condition.strip();
    }

    /** Why {@code condition} cannot be read ("at character 15: ..."), or null when it can. */
    public static @Nullable String problem(String condition) {
        try {
            StreamCondition.parse(condition, Contributions.workbench().codecs());
            return null;
        } catch (ConditionException e) {
            return e.getMessage();
        }
    }

    private static String message(String text, int hitCount) {
        return "Robot data breakpoint: " + text + (hitCount > 0 ? " [hit count: " + hitCount + "]" : "");
    }

    @Override
    public String getModelIdentifier() {
        return MODEL;
    }

    public String condition() {
        IMarker m = getMarker();
        return m == null ? "" : m.getAttribute(CONDITION, "");
    }

    public void setCondition(String condition) throws CoreException {
        String text = check(condition);
        setAttributes(new String[] { CONDITION, IMarker.MESSAGE }, new Object[] { text, message(text, hitCount()) });
    }

    public int hitCount() {
        IMarker m = getMarker();
        return m == null ? 0 : m.getAttribute(HIT_COUNT, 0);
    }

    public void setHitCount(int n) throws CoreException {
        setAttributes(new String[] { HIT_COUNT, IMarker.MESSAGE }, new Object[] { Math.max(0, n), message(condition(), n) });
    }

    /** Why it last stopped, or "". */
    public String lastHit() {
        IMarker m = getMarker();
        return m == null ? "" : m.getAttribute(LAST_HIT, "");
    }

    void setLastHit(String why) throws CoreException {
        setAttribute(LAST_HIT, why);
    }

    /** The condition read with the workbench's codecs, or null when it no longer reads (say why with {@link #problem}). */
    @Nullable StreamCondition parsed() {
        try {
            return StreamCondition.parse(condition(), Contributions.workbench().codecs());
        } catch (ConditionException e) {
            return null;
        }
    }
}
