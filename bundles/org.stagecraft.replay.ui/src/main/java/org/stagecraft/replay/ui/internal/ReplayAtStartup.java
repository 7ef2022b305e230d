package org.stagecraft.replay.ui.internal;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Platform;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.ui.IStartup;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchListener;
import org.eclipse.ui.PlatformUI;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.play.ReplayClock;
import org.stagecraft.replay.play.ReplayLoop;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.streams.StreamBus;

/**
 * With STAGECRAFT_REPLAY=/path/to/a/log in the environment (a recorded trace, a spy log or a Player
 * writelog file), the workbench replays that log onto its stream bus at the recorded pace, in a loop,
 * with the {@link Replayer} the Session Log editor uses: the Robot Views show it under the keys the
 * live spy would have used, as if the robot were running. For demonstrations and screenshots; without
 * the variable this does nothing.
 */
public final class ReplayAtStartup implements IStartup {
    public static final String VARIABLE = "STAGECRAFT_REPLAY";

    @Override
    public void earlyStartup() {
        String file = System.getenv(VARIABLE);
        if (file == null || file.isBlank()) {
            return;
        }
        ILog log = ILog.of(Platform.getBundle("org.stagecraft.replay.ui"));
        Path path = Path.of(file);
        if (!Files.isReadable(path)) {
            log.warn(VARIABLE + ": cannot read " + path);
            return;
        }
        try {
            Running running = start(path, WorkbenchBus.get());
            closeAtShutdown(running, log);
            log.info("replaying " + path + " onto the workbench stream bus, in a loop");
        } catch (IOException e) {
            log.error(VARIABLE + ": cannot replay " + path + ": " + e.getMessage());
        }
    }

    /** A log being replayed in a loop; closing stops the replay and closes the log. */
    public record Running(Replayer replayer, SessionLog log) implements AutoCloseable {
        @Override
        public void close() throws IOException {
            replayer.close();
            log.close();
        }
    }

    /** Opens {@code path} and replays it onto {@code bus} in a loop, the bus's world model listening first. */
    public static Running start(Path path, StreamBus bus) throws IOException {
        // the bus's world model must listen before the first geometry reply is replayed
        SharedWorld.of(bus);
        SessionLog sessionLog = SessionLogs.open(path, Contributions.workbench().codecs()); // contributed decoders too
        try {
            Replayer replayer = new Replayer(sessionLog, bus, ReplayClock.system());
            ReplayLoop.start(replayer);
            return new Running(replayer, sessionLog);
        } catch (IOException | RuntimeException e) {
            sessionLog.close();
            throw e;
        }
    }

    /** An imported trace lives in a temporary spy log, which closing deletes. */
    private static void closeAtShutdown(Running running, ILog log) {
        PlatformUI.getWorkbench().addWorkbenchListener(new IWorkbenchListener() {
            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public boolean preShutdown(IWorkbench workbench, boolean forced) {
                return true;
            }

            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public void postShutdown(IWorkbench workbench) {
                try {
                    running.close();
                } catch (IOException e) {
                    log.warn(VARIABLE + ": closing " + running.log().path() + ": " + e.getMessage());
                }
            }
        });
    }
}
