package org.stagecraft.spy.proxy;

import java.io.IOException;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.log.HoldEntry;

/**
 * Where the spy records a session (the MCAP spy log). Called on the observation thread only. An
 * IOException (e.g. a full disk) stops recording; forwarding and publishing go on.
 */
public interface SpyRecorder extends AutoCloseable {
    void opened(ConnectionInfo connection, long timeNanos) throws IOException;

    void closed(ConnectionInfo connection, long timeNanos, String reason) throws IOException;

    void wire(ConnectionInfo connection, Direction dir, WireEvent event, long timeNanos) throws IOException;

    void diagnostic(ConnectionInfo connection, Direction dir, long streamOffset, String text, long timeNanos)
            throws IOException;

    /** What a robot hold did or became (Stagecraft's own record, apart from the wire). */
    default void hold(HoldEntry entry) throws IOException {
    }

    /**
     * Puts what was recorded so far into the log file, so that it survives the process being killed
     * (called every few tens of milliseconds while there is traffic, and at least once a second); a
     * recorder forces the file to the disk at most about once a second.
     */
    void flush() throws IOException;

    /** Wire messages and their wire bytes that reached the log file so far. */
    record Logged(long messages, long bytes) {
    }

    /**
     * What is in the log file so far ({@link Logged}), for saying what was relayed but not logged when
     * the log stopped early; null when this recorder cannot tell.
     */
    default @Nullable Logged logged() {
        return null;
    }

    @Override
    void close() throws IOException;
}
