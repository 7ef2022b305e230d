package org.stagecraft.replay.session;

import java.io.IOException;
import java.nio.file.Path;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.play.ReplayClock;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.streams.StreamBus;

/** What one background reading of the file produced: the log and its replayer, or why there is none. */
record OpenedLog(@Nullable SharedLog shared, @Nullable Replayer replayer, @Nullable Exception error, long costNanos) {
    static OpenedLog read(Path file, CodecRegistry codecs, StreamBus bus, SharedLog.CloseFailure onCloseFailure) {
        long started = System.nanoTime();
        SessionLog l = null;
        try {
            l = SessionLogs.open(file, codecs);
            SharedLog s = new SharedLog(l, onCloseFailure);
            return new OpenedLog(s, new Replayer(l, bus, ReplayClock.system()), null, System.nanoTime() - started);
        } catch (IOException | RuntimeException e) {
            if (l != null) {
                try {
                    l.close();
                } catch (IOException ignored) {
                    // the open already failed; that is what is reported
                }
            }
            return new OpenedLog(null, null, e, System.nanoTime() - started);
        }
    }
}
