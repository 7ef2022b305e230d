package org.stagecraft.tools.ui.breakpoints;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.dialogs.ErrorDialog;
import org.eclipse.jface.dialogs.InputDialog;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Edit Condition… and Hit Count… on a robot data breakpoint selected in the Breakpoints view (the command's
 * parameter {@link #WHAT} says which).
 */
public final class EditRobotDataBreakpointHandler extends AbstractHandler {
    public static final String WHAT = "org.stagecraft.tools.ui.robotDataEdit";

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) {
        if (!(HandlerUtil.getCurrentSelection(event) instanceof IStructuredSelection sel)
                || !(sel.getFirstElement() instanceof RobotDataBreakpoint b)) {
            return null;
        }
        Shell shell = HandlerUtil.getActiveShell(event);
        boolean hitCount = "hitCount".equals(event.getParameter(WHAT));
        InputDialog d = hitCount
                ? new InputDialog(shell, "Robot Data Breakpoint Hit Count",
                        "Stop on this hit only, then disable the breakpoint (0: stop on every hit):", Integer.toString(b.hitCount()),
                        t -> t.strip().matches("\\d{1,9}") ? null : "a whole number, 0 or more")
                : new InputDialog(shell, "Robot Data Breakpoint Condition", "Stop when a message from Player satisfies:",
                        b.condition(), RobotDataBreakpoint::problem);
        if (d.open() != Window.OK) {
            return null;
        }
        try {
            if (hitCount) {
                b.setHitCount(Integer.parseInt(d.getValue().strip()));
            } else {
                b.setCondition(d.getValue());
            }
        } catch (CoreException e) {
            ErrorDialog.openError(shell, "Robot Data Breakpoint", null, e.getStatus());
        }
        return null;
    }
}
