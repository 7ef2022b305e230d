package org.stagecraft.replay.session;

import java.io.IOException;

import org.stagecraft.replay.log.SessionLog;

/**
 * An open log read by several threads (the replay, the timeline pass, the inspector's and the plot's
 * readers): when the editor replaces it (a reload, following a growing file) it is retired, and closed
 * only once the last reader has released it, so no reader fails half way through with a closed file.
 * A reader that comes after the close is told so by {@link #acquire()} and skips its work (its result
 * would be for a log no longer shown).
 */
public final class SharedLog {
    /** Told about a close that failed (the log was read; only releasing the file went wrong). */
    public interface CloseFailure {
        void failed(SessionLog log, IOException e);
    }

    private final SessionLog log;
    private final CloseFailure onFailure;
    private int readers;
    private boolean retired;
    private boolean closed;

    public SharedLog(SessionLog log, CloseFailure onFailure) {
        this.log = log;
        this.onFailure = onFailure;
    }

    public SessionLog log() {
        return log;
    }

    /** Takes the log for reading until {@link #release()}; false when it is already closed. */
    public synchronized boolean acquire() {
        if (closed) {
            return false;
        }
        readers++;
        return true;
    }

    /** Ends a reading {@link #acquire()} began; closes a retired log its last reader leaves. */
    public void release() {
        boolean close;
        synchronized (this) {
            if (readers == 0) {
                throw new IllegalStateException("released more often than acquired: " + log.path());
            }
            readers--;
            close = shouldClose();
        }
        if (close) {
            closeLog();
        }
    }

    /** No new use is expected: closes the log now if nobody reads it, else when the last reader leaves. */
    public void retire() {
        boolean close;
        synchronized (this) {
            retired = true;
            close = shouldClose();
        }
        if (close) {
            closeLog();
        }
    }

    public synchronized boolean isClosed() {
        return closed;
    }

    /** Call with the lock: whether this caller is the one to close the file now. */
    private boolean shouldClose() {
        if (retired && readers == 0 && !closed) {
            closed = true;
            return true;
        }
        return false;
    }

    private void closeLog() {
        try {
            log.close();
        } catch (IOException e) {
            onFailure.failed(log, e);
        }
    }
}
