package org.stagecraft.spy.log;

import org.eclipse.jdt.annotation.Nullable;

/**
 * One connection of a spy log.
 *
 * @param port         the port the robot program connected to (the port of its wire channels), or -1 if
 *                     no byte travelled and the listen address names none
 * @param openedNanos  log time of the open event, or -1 if the log has none (it was cut off)
 * @param closedNanos  log time of the close event, or -1 if the log has none (still open when the log
 *                     ended, or cut off)
 * @param closeReason  why it closed, or null
 */
public record LogConnection(int conn, int port, @Nullable String client, @Nullable String listen, @Nullable String upstream, long openedNanos,
        long closedNanos, @Nullable String closeReason) {

    public boolean closed() {
        return closedNanos >= 0;
    }
}
