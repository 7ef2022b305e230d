package org.stagecraft.views.internal;

import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Platform;
import org.eclipse.ui.IStartup;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.scene.TraceMessages;
import org.stagecraft.scene.TraceReplay;

/**
 * At workbench start: creates the workbench bus's shared world model (so no geometry reply is missed).
 * With STAGECRAFT_REPLAY=/path/to/x.trace.jsonl in the environment, the workbench replays that recorded
 * session onto its stream bus at the recorded pace, in a loop, keyed as the spy would key it (Player on
 * 127.0.0.1:6665): the Robot Views show it as if the robot were running. For demonstrations and
 * screenshots; without the variable this does nothing.
 */
public final class WorkbenchStartup implements IStartup {
    public static final String VARIABLE = "STAGECRAFT_REPLAY";

    @Override
    public void earlyStartup() {
        // the workbench's world model listens from the start: geometry replies come once, maybe long
        // before the first Robot View opens
        SharedWorld.of(WorkbenchBus.get());
        String file = System.getenv(VARIABLE);
        if (file == null || file.isBlank()) {
            return;
        }
        ILog log = ILog.of(Platform.getBundle("org.stagecraft.views"));
        Path trace = Path.of(file);
        if (!Files.isReadable(trace)) {
            log.warn(VARIABLE + ": cannot read " + trace);
            return;
        }
        try {
            TraceReplay.start(TraceMessages.read(trace, "127.0.0.1:6665"), WorkbenchBus.get(), true);
            log.info("replaying " + trace + " onto the workbench stream bus");
        } catch (Exception e) {
            log.error(VARIABLE + ": cannot replay " + trace + ": " + e.getMessage(), e);
        }
    }
}
