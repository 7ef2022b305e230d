package org.stagecraft.tools.ui.view;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.ui.handlers.HandlerUtil;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.ui.launch.RunningSessions;
import org.stagecraft.tools.ui.launch.SessionParts;
import org.stagecraft.tools.world.WorldFreeze;
import org.stagecraft.tools.world.WorldState;

/**
 * Show Stage's Window (Tools view toolbar, Run menu): brings the Stage window of each running Robot Session
 * to the front. Stage's window is another process's, which the workbench cannot raise, so the session's world
 * driver, inside Stage's process, raises it (docs/debugging-robots.md).
 */
public final class ShowStageWindowHandler extends AbstractHandler {
    public static final String COMMAND = "org.stagecraft.tools.ui.showStageWindow";

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) {
        List<String> said = raiseAll();
        if (!said.isEmpty()) {
            MessageDialog.openInformation(HandlerUtil.getActiveShell(event), "Show Stage's Window", String.join("\n", said));
        }
        return null;
    }

    /** Raises every running session's Stage window; returns what to tell the user (nothing when all went well). */
    public static List<String> raiseAll() {
        List<String> said = new ArrayList<>();
        int sessions = 0;
        for (SessionParts parts : RunningSessions.running()) {
            RobotSession s = parts.session();
            if (s == null) {
                continue;
            }
            sessions++;
            WorldFreeze world = s.world();
            if (world == null) {
                said.add(parts.sessionName() + ": no world driver in this session, so its Stage window cannot be raised"
                        + (s.worldProblem().isEmpty() ? "" : " (" + s.worldProblem() + ")"));
                continue;
            }
            try {
                WorldState state = world.raiseWindow().get(5, TimeUnit.SECONDS);
                if (!state.gui()) {
                    said.add(parts.sessionName() + ": Stage runs without a window in this session");
                }
            } catch (ExecutionException e) {
                said.add(parts.sessionName() + ": " + e.getCause().getMessage());
            } catch (TimeoutException e) {
                said.add(parts.sessionName() + ": the world driver did not answer within 5 s");
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        if (sessions == 0) {
            said.add("No Robot Session is running.");
        }
        return said;
    }
}
