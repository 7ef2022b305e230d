package org.stagecraft.tools.ui.breakpoints;

import org.eclipse.core.resources.IMarker;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.debug.ui.DebugUITools;
import org.eclipse.debug.ui.IDebugModelPresentation;
import org.eclipse.debug.ui.IDebugUIConstants;
import org.eclipse.debug.ui.IValueDetailListener;
import org.eclipse.jface.viewers.ILabelProviderListener;
import org.eclipse.swt.graphics.Image;
import org.eclipse.ui.IEditorInput;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;

/**
 * How the Breakpoints view shows a robot data breakpoint: its condition, its hit count and why it last
 * stopped, e.g. "Robot data: laser:0 min(ranges) < 0.3 [hit count: 3] — last: laser:0 min(ranges) = 0.287 m < 0.3".
 */
@NonNullByDefault({}) // the platform's unannotated interface
public final class RobotDataBreakpointPresentation implements IDebugModelPresentation {

    /** The label, also for tests. */
    public static String label(RobotDataBreakpoint b) {
        int n = b.hitCount();
        String last = b.lastHit();
        return "Robot data: " + b.condition() + (n > 0 ? " [hit count: " + n + "]" : "") + (last.isEmpty() ? "" : " — last: " + last);
    }

    @Override
    public @Nullable String getText(Object element) {
        return element instanceof RobotDataBreakpoint b ? label(b) : null;
    }

    @Override
    public @Nullable Image getImage(Object element) {
        if (!(element instanceof RobotDataBreakpoint b)) {
            return null;
        }
        boolean enabled;
        try {
            enabled = b.isEnabled();
        } catch (CoreException e) {
            enabled = false;
        }
        return DebugUITools.getImage(enabled ? IDebugUIConstants.IMG_OBJS_BREAKPOINT : IDebugUIConstants.IMG_OBJS_BREAKPOINT_DISABLED);
    }

    @Override
    public void setAttribute(String attribute, Object value) {
    }

    @Override
    public void computeDetail(org.eclipse.debug.core.model.IValue value, IValueDetailListener listener) {
        listener.detailComputed(value, "");
    }

    @Override
    public @Nullable IEditorInput getEditorInput(Object element) {
        return null;
    }

    @Override
    public @Nullable String getEditorId(IEditorInput input, Object element) {
        return null;
    }

    @Override
    public void addListener(ILabelProviderListener listener) {
    }

    @Override
    public void dispose() {
    }

    @Override
    public boolean isLabelProperty(Object element, String property) {
        return IMarker.MESSAGE.equals(property);
    }

    @Override
    public void removeListener(ILabelProviderListener listener) {
    }
}
