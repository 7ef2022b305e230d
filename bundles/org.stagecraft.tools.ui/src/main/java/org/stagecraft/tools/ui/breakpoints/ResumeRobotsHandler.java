package org.stagecraft.tools.ui.breakpoints;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Resume Robots: ends the robot data breakpoint hit of every running session, for a program that is not
 * being debugged (a debugged one is resumed with the debugger's Resume).
 */
public final class ResumeRobotsHandler extends AbstractHandler {
    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) {
        RobotDataBreakpoints.get().resumeAll();
        return null;
    }
}
