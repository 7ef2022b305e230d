package org.stagecraft.tools.ui.breakpoints;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.dialogs.ErrorDialog;
import org.eclipse.jface.dialogs.InputDialog;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Add Robot Data Breakpoint… (Breakpoints view, Run menu, and the inspector's and Robot View's context
 * menus, which pass a condition to start from in the parameter {@link #CONDITION_PARAMETER}): asks for the
 * condition, refusing one that does not read with where and why, and adds the breakpoint.
 */
public final class AddRobotDataBreakpointHandler extends AbstractHandler {
    public static final String COMMAND = "org.stagecraft.tools.ui.addRobotDataBreakpoint";
    public static final String CONDITION_PARAMETER = "org.stagecraft.tools.ui.robotDataCondition";
    static final String EXAMPLE = "laser:0 min(ranges) < 0.3";

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) {
        Shell shell = HandlerUtil.getActiveShell(event);
        String start = event.getParameter(CONDITION_PARAMETER);
        InputDialog d = new InputDialog(shell, "Add Robot Data Breakpoint",
                "Stop the robot program when a message from Player satisfies (a device, then a test of its fields,\n"
                        + "e.g. laser:0 min(ranges) < 0.3, ranger:1 ranges[3] < 50 cm, position2d:0 stall == 1, bumper:0 any(bumpers)):",
                start == null || start.isBlank() ? EXAMPLE : start, RobotDataBreakpoint::problem);
        if (d.open() != Window.OK) {
            return null;
        }
        try {
            RobotDataBreakpoint.create(d.getValue(), 0);
        } catch (CoreException e) {
            ErrorDialog.openError(shell, "Add Robot Data Breakpoint", null, e.getStatus());
        }
        return null;
    }
}
