package org.stagecraft.views.internal;

import org.eclipse.ui.IStartup;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.scene.SharedWorld;

/**
 * At workbench start: creates the workbench bus's shared world model, so no geometry reply is missed.
 * (Replaying a log onto the workbench bus at start, STAGECRAFT_REPLAY, is the replay UI's job:
 * {@code org.stagecraft.replay.ui.internal.ReplayAtStartup}.)
 */
public final class WorkbenchStartup implements IStartup {

    @Override
    public void earlyStartup() {
        // the workbench's world model listens from the start: geometry replies come once, maybe long
        // before the first Robot View opens
        SharedWorld.of(WorkbenchBus.get());
    }
}
