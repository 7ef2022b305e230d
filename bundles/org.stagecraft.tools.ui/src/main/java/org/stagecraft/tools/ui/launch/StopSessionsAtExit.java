package org.stagecraft.tools.ui.launch;

import org.eclipse.ui.IStartup;
import org.eclipse.ui.PlatformUI;

/** Puts {@link ExitWithRunningSessions} on the workbench when it starts. */
public final class StopSessionsAtExit implements IStartup {
    @Override
    public void earlyStartup() {
        PlatformUI.getWorkbench().addWorkbenchListener(new ExitWithRunningSessions());
    }
}
