package org.stagecraft.spy.proxy;

/**
 * Something about a connection that the user should see at once, not only in the log: Player (the
 * upstream) not answering, or observation failing. The command line prints it on stderr; the IDE shows it in the spy's
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
        UPSTREAM_REFUSED,
        /**
         * Observing failed (a bug, a missing class, a log that broke): the wire goes on, but what the
         * spy shows and records is incomplete from here; the bytes concerned are counted as unobserved.
         */
        OBSERVATION_FAILED,
        /**
         * Observation made no progress for the wait limit (a hung disk, a stuck log): forwarding stopped
         * waiting for it, and what it cannot take is left out of observation (counted, logged as gaps)
         * until it moves again.
         */
        OBSERVATION_STALLED;

        /** Whether something was lost (a robot program's connection, or observation), not just delayed. */
        public boolean isFailure() {
            return this == UPSTREAM_REFUSED || this == OBSERVATION_FAILED || this == OBSERVATION_STALLED;
        }
    }

    @Override
    public String toString() {
        return text;
    }
}
