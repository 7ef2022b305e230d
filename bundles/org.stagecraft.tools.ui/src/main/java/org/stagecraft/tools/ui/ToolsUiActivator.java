package org.stagecraft.tools.ui;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.osgi.framework.BundleActivator;
import org.osgi.framework.BundleContext;
import org.stagecraft.tools.ui.foxglove.FoxgloveLive;
import org.stagecraft.tools.ui.launch.RunningSessions;

/**
 * Stops the running Robot Sessions when this plug-in stops (the IDE exits, or the plug-in is
 * stopped), while the plug-ins a session's stop needs (streams, spy, recording) are still there: OSGi
 * stops this plug-in before those it requires. Stopping them later, from a JVM shutdown hook, failed
 * with NoClassDefFoundErrors once their class loaders were gone.
 */
public final class ToolsUiActivator implements BundleActivator {
    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void start(BundleContext context) {
        // nothing to do: sessions register themselves when they start
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void stop(BundleContext context) {
        RunningSessions.stopAll();
        FoxgloveLive.get().shutdown();
    }
}
