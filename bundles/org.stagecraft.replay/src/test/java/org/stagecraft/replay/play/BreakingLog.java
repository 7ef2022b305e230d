package org.stagecraft.replay.play;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.spy.proxy.ConnectionInfo;

/** A real log whose cursors fail with a runtime exception at the n-th message read forward: a decoder bug. */
final class BreakingLog implements SessionLog {
    private final SessionLog log;
    private final int breakAt;

    BreakingLog(SessionLog log, int breakAt) {
        this.log = log;
        this.breakAt = breakAt;
    }

    @Override
    public LogCursor cursor(long timeNanos) throws IOException {
        LogCursor c = log.cursor(timeNanos);
        return new LogCursor() {
            private int read;

            @Override
            public void seek(long t) throws IOException {
                c.seek(t);
            }

            @Override
            public void seekTo(LogMessage m) throws IOException {
                c.seekTo(m);
            }

            @Override
            public LogMessage next() throws IOException {
                if (++read == breakAt) {
                    throw new IllegalStateException("a decoder bug at message " + breakAt);
                }
                return c.next();
            }

            @Override
            public LogMessage previous() throws IOException {
                return c.previous();
            }

            @Override
            public void close() throws IOException {
                c.close();
            }
        };
    }

    @Override
    public Path path() {
        return log.path();
    }

    @Override
    public LogFormat format() {
        return log.format();
    }

    @Override
    public long startNanos() {
        return log.startNanos();
    }

    @Override
    public long endNanos() {
        return log.endNanos();
    }

    @Override
    public boolean complete() {
        return log.complete();
    }

    @Override
    public long messageCount() {
        return log.messageCount();
    }

    @Override
    public List<ConnectionInfo> connections() {
        return log.connections();
    }

    @Override
    public List<LogProblem> problems() {
        return log.problems();
    }

    @Override
    public void close() throws IOException {
        log.close();
    }
}
