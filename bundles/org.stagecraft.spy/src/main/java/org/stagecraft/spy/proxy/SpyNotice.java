package org.stagecraft.spy.proxy;

/**
 * Something about a connection that the user should see at once, not only in the log: Player (the
 * upstream) not answering. The command line prints it on stderr; the IDE shows it in the spy's
 * console, the Tools view and the Error Log.
 *
 * @param connection the robot program's connection concerned
 * @param kind       what happened
 * @param text       a complete sentence naming the addresses involved
 */
public record SpyNotice(ConnectionInfo connection, Kind kind, String text) {
    public enum Kind {
        /** The upstream refused; the spy keeps retrying for the grace period. */
        UPSTREAM_WAITING,
        /** The upstream accepted after refusing at first; the connection is relayed normally. */
        UPSTREAM_REACHED,
        /** The upstream still refused when the grace period ended; the robot program's connection was closed. */
        UPSTREAM_REFUSED;

        /** Whether the robot program lost its connection (an error), not just waited. */
        public boolean isFailure() {
            return this == UPSTREAM_REFUSED;
        }
    }

    @Override
    public String toString() {
        return text;
    }
}
