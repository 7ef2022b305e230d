package org.stagecraft.replay.ui.internal;

import java.util.Map;

import org.eclipse.core.commands.Command;
import org.eclipse.core.commands.ParameterizedCommand;
import org.eclipse.swt.widgets.Label;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.handlers.IHandlerService;

/**
 * Runs the Tool Manager's Add Robot Data Breakpoint command with a condition to start from. By the command's id,
 * not a class: the Session Log editor does not need the Tool Manager, and says so when it is not installed.
 */
final class AddDataBreakpoint {
    static final String COMMAND = "org.stagecraft.tools.ui.addRobotDataBreakpoint";
    static final String CONDITION = "org.stagecraft.tools.ui.robotDataCondition";

    private AddDataBreakpoint() {
    }

    static void ask(String condition, Label status) {
        ICommandService commands = PlatformUI.getWorkbench().getService(ICommandService.class);
        IHandlerService handlers = PlatformUI.getWorkbench().getService(IHandlerService.class);
        Command c = commands == null ? null : commands.getCommand(COMMAND);
        if (c == null || !c.isDefined() || handlers == null) {
            status.setText("Robot data breakpoints need the Stagecraft Tool Manager (org.stagecraft.tools.ui)");
            return;
        }
        try {
            handlers.executeCommand(ParameterizedCommand.generateCommand(c, Map.of(CONDITION, condition)), null);
        } catch (Exception e) { // the command's own dialog reports what goes wrong with the condition
            status.setText("Add Robot Data Breakpoint: " + e.getMessage());
        }
    }
}
