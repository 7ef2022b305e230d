package org.stagecraft.tools.ui.foxglove;

import org.eclipse.ui.IStartup;

/** When the workbench starts: serve at once if the preference is on, and follow it from then on. */
public final class FoxgloveLiveStartup implements IStartup {
    @Override
    public void earlyStartup() {
        FoxgloveLive.get().followPreferences();
    }
}
