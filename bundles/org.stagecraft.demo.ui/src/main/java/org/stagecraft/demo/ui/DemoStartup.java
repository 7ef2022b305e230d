package org.stagecraft.demo.ui;

import org.eclipse.ui.IStartup;
import org.eclipse.ui.PlatformUI;

/** Starts the demo once the workbench is up, when the product was started by {@code ./stagecraft demo}. */
public final class DemoStartup implements IStartup {

    @Override
    public void earlyStartup() {
        DemoOptions options = DemoOptions.fromSystemProperties();
        if (!options.enabled()) {
            return;
        }
        new DemoRun(options, PlatformUI.getWorkbench().getDisplay()).start();
    }
}
