package org.stagecraft.tools.ui;

import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;

/**
 * Toolbar toggles whose state changes on other threads (a session starting, a server stopping):
 * their buttons are refreshed later, on the UI thread, and not at all once the workbench is gone.
 */
public final class CommandButtons {
    private CommandButtons() {
    }

    /** A task, safe to run on any thread, that refreshes every button of {@code commandId}. */
    public static Runnable refresher(String commandId) {
        return () -> {
            if (!PlatformUI.isWorkbenchRunning()) {
                return;
            }
            Display d = PlatformUI.getWorkbench().getDisplay();
            if (!d.isDisposed()) {
                d.asyncExec(() -> {
                    if (PlatformUI.isWorkbenchRunning()) {
                        @Nullable ICommandService cs = PlatformUI.getWorkbench().getService(ICommandService.class);
                        if (cs != null) {
                            cs.refreshElements(commandId, null);
                        }
                    }
                });
            }
        };
    }
}
