package org.stagecraft.replay.log;

/** The kinds of file a {@link SessionLog} can come from. */
public enum LogFormat {
    /** The Network Spy's MCAP log. */
    SPY_LOG,
    /** A recorded trace ({@code *.trace.jsonl}, format {@code player-trace}). */
    PLAYER_TRACE,
    /** Player's {@code writelog} driver's text log. */
    WRITELOG
}
