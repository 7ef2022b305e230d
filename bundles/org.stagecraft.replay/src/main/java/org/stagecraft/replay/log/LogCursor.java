package org.stagecraft.replay.log;

import java.io.IOException;

import org.eclipse.jdt.annotation.Nullable;

/**
 * A position between two messages of a {@link SessionLog} that moves both ways. Seeking uses the
 * file's index where it has one, so it costs about the same anywhere in a large log.
 */
public interface LogCursor extends AutoCloseable {

    /** Moves before the first message whose time is at or after {@code timeNanos}. */
    void seek(long timeNanos) throws IOException;

    /** Moves before {@code message}, so that {@link #next()} returns it (a message from this log). */
    void seekTo(LogMessage message) throws IOException;

    /** The message after the cursor, moving past it; null at the end of the log. */
    @Nullable LogMessage next() throws IOException;

    /** The message before the cursor, moving back before it; null at the start of the log. */
    @Nullable LogMessage previous() throws IOException;

    @Override
    void close() throws IOException;
}
