package org.stagecraft.views;

import java.util.Map;
import java.util.function.Consumer;

import org.eclipse.core.commands.Command;
import org.eclipse.core.commands.ParameterizedCommand;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.handlers.IHandlerService;

/**
 * Runs the Tool Manager's Add Robot Data Breakpoint command with a condition to start from (docs/debugging-robots.md).
 * By the command's id, not a class: the views that offer breakpoints (the Robot View, the Session Log editor's
 * inspector) do not need the Tool Manager, and say so when it is not installed.
 */
public final class RobotDataBreakpointCommand {
    public static final String COMMAND = "org.stagecraft.tools.ui.addRobotDataBreakpoint";
    public static final String CONDITION = "org.stagecraft.tools.ui.robotDataCondition";

    private RobotDataBreakpointCommand() {
    }

    /**
     * Opens the command's dialog with {@code condition} (UI thread).
     *
     * @param problem told, for the user, when the command is missing or fails
     */
    public static void ask(String condition, Consumer<String> problem) {
        ICommandService commands = PlatformUI.getWorkbench().getService(ICommandService.class);
        IHandlerService handlers = PlatformUI.getWorkbench().getService(IHandlerService.class);
        Command c = commands == null ? null : commands.getCommand(COMMAND);
        if (c == null || !c.isDefined() || handlers == null) {
            problem.accept("Robot data breakpoints need the Stagecraft Tool Manager (org.stagecraft.tools.ui)");
            return;
        }
        try {
            handlers.executeCommand(ParameterizedCommand.generateCommand(c, Map.of(CONDITION, condition)), null);
        } catch (Exception e) { // the command's own dialog reports what goes wrong with the condition
            problem.accept("Add Robot Data Breakpoint: " + e.getMessage());
        }
    }
}
