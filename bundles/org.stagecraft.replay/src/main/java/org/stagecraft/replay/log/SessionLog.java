package org.stagecraft.replay.log;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A recorded session opened for replay and analysis: a spy log (MCAP), a recorded trace or a Player
 * {@code writelog} file, all seen the same way, as a time-ordered sequence of {@link LogMessage}s.
 * Implementations keep memory flat in the file's size: they read through an index or stream the
 * file, never hold all messages. Open one with {@link SessionLogs#open(Path)}.
 */
public interface SessionLog extends AutoCloseable {

    Path path();

    LogFormat format();

    /** Log time of the first message, in nanoseconds on the recorder's clock. */
    long startNanos();

    /** Log time of the last message. */
    long endNanos();

    /**
     * Whether the file is known to be whole: false for a spy log without its summary, which is one
     * a running spy is still writing (or one that was cut off); such a file may grow, and opening it
     * again shows more.
     */
    boolean complete();

    /** Wire entries in the log (banners, Player messages, unframed pieces), from its index; events not counted. */
    long messageCount();

    /** The connections the log knows, in connection-number order. */
    List<ConnectionInfo> connections();

    /**
     * What went wrong reading the file (empty when nothing did): e.g. where a truncated or corrupt
     * file stopped being readable. The readable part still replays.
     */
    List<LogProblem> problems();

    /**
     * What Stagecraft's robot holds did during the session (docs/debugging-robots.md): injected zero
     * commands, held-back program messages, holds on and off. Empty for logs without holds and for
     * formats that cannot record them.
     */
    default List<HoldEntry> holdEntries() throws IOException {
        return List.of();
    }

    /**
     * The {@link #holdEntries()} as rows for the packet inspector ({@link LogMessage.Kind#HOLD}), in log
     * order: each with its connection, its direction (towards Player for injected and held-back program
     * messages, towards the program for a breakpoint's hit), the message it carried decoded, and a text
     * that says what happened.
     */
    default List<LogMessage> holdRows() throws IOException {
        return List.of();
    }

    /**
     * A new cursor positioned before the first message whose time is at or after {@code timeNanos}.
     * Each cursor is independent; a cursor is used by one thread at a time.
     */
    LogCursor cursor(long timeNanos) throws IOException;

    @Override
    void close() throws IOException;
}
