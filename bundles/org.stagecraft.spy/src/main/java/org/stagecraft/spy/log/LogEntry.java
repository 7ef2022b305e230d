package org.stagecraft.spy.log;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;

/**
 * One record of a spy log, in log-time order. Times are epoch nanoseconds: the log time, which is the
 * spy's receive time except that it never goes back in the file (see {@link SpyLogWriter}); a wire
 * entry also has its exact receive time, {@link Wire#captureNanos()}.
 */
public sealed interface LogEntry {

    long timeNanos();

    /** Connection number, in accept order. */
    int conn();

    /** What a {@link Wire} entry holds: one event of the lossless framer. */
    enum Kind {
        /** The 32-byte ident a Player server sends first. */
        BANNER,
        /** One complete Player message: 40-byte header and payload. */
        FRAME,
        /** Bytes that are not a message (corruption, a stream that ended mid-message). */
        UNFRAMED
    }

    /** A robot program connected to the spy, which connected on to Player. */
    record Opened(long timeNanos, int conn, String client, String listen, String upstream) implements LogEntry {
    }

    /** The connection ended. */
    record Closed(long timeNanos, int conn, String reason) implements LogEntry {
    }

    /**
     * Exactly the wire bytes of one framer event, at its offset in its stream (connection + direction).
     *
     * @param reason       why the bytes are {@link Kind#UNFRAMED}; empty for banners and frames
     * @param captureNanos when the spy received the bytes, exactly (MCAP's publish time); equal to
     *                     {@code timeNanos} unless another thread's entry was logged before with a later time
     */
    record Wire(long timeNanos, int conn, int port, Direction dir, long streamOffset, Kind kind, byte[] bytes,
            String reason, long captureNanos) implements LogEntry {
        public Wire {
            bytes = bytes.clone();
            reason = reason == null ? "" : reason;
        }

        /** An entry captured at its log time. */
        public Wire(long timeNanos, int conn, int port, Direction dir, long streamOffset, Kind kind, byte[] bytes,
                String reason) {
            this(timeNanos, conn, port, dir, streamOffset, kind, bytes, reason, timeNanos);
        }

        /** A fresh copy of the bytes. */
        @Override
        public byte[] bytes() {
            return bytes.clone();
        }

        public int length() {
            return bytes.length;
        }

        /** Streams the bytes without copying (callers must not modify them). */
        byte[] bytesUnsafe() {
            return bytes;
        }
    }

    /**
     * Something the spy noticed about a stream, e.g. a decode problem.
     *
     * @param dir the stream's direction, or null if the diagnostic is about the connection
     */
    record Diagnostic(long timeNanos, int conn, @Nullable Direction dir, long streamOffset, String text) implements LogEntry {
    }
}
