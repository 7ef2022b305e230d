package org.stagecraft.spy.log;

/**
 * Something Stagecraft itself did to a robot program's streams while a robot hold was on (see
 * docs/debugging-robots.md): bytes it injected towards Player, program bytes it held back, the
 * hold switching on or off, a robot data breakpoint holding Player's messages back from the program, or the
 * simulated world frozen and thawed. These entries live on the log's own {@code /stagecraft/hold} channel, apart
 * from the wire channels, which keep recording exactly what the program sent; with both,
 * {@link SpyLogReader#upstreamBytes} rebuilds what Player received.
 *
 * @param conn           the connection, 0 for hold on/off and the world's freezes (they concern the session)
 * @param port           the connection's port (0 for hold on/off)
 * @param programOffset  offset in the program's client-to-server stream: injected bytes went to Player
 *                       just before the program's byte at this offset; held-back bytes start here
 * @param upstreamOffset offset in the stream Player received at which the injected bytes start, or at
 *                       which the held-back bytes would have been
 * @param bytes          the injected or held-back bytes (empty for hold on/off)
 * @param text           what and why, for people: e.g. "zero velocity to position2d:0 (suspended in the debugger)"
 */
public record HoldEntry(long timeNanos, int conn, int port, Action action, long programOffset, long upstreamOffset,
        byte[] bytes, String text) {

    public enum Action {
        /** Stagecraft sent these bytes to Player; the program did not. */
        INJECTED,
        /** The program sent these bytes; Stagecraft did not forward them to Player. */
        HELD_BACK,
        /** A hold began (text: the reasons). */
        HOLD_ON,
        /** The hold ended. */
        HOLD_OFF,
        /**
         * A robot data breakpoint held on the Player message at {@code programOffset} of the
         * Player-to-program stream ({@code bytes}: that message; text: the breakpoint and its values). The
         * message and what followed it were held back from the program until {@link #PASSED_ON}.
         */
        BREAK,
        /**
         * The Player messages held back since the {@link #BREAK} at {@code programOffset} went on to the
         * program (text: after how long, and why). They are in the wire channel as always, with the time
         * they were passed on.
         */
        PASSED_ON,
        /**
         * Stagecraft stopped the simulated world of the session's Player (conn 0; text: the simulated time it
         * stopped at and why). Nothing in it moves, and its simulated time stands, until {@link #WORLD_THAWED}.
         */
        WORLD_FROZEN,
        /** The simulated world runs on from where it stopped (conn 0; text: the simulated time and how long). */
        WORLD_THAWED
    }

    public HoldEntry {
        bytes = bytes == null ? new byte[0] : bytes.clone();
        text = text == null ? "" : text;
    }

    @Override
    public byte[] bytes() {
        return bytes.clone();
    }

    public int length() {
        return bytes.length;
    }

    byte[] bytesUnsafe() {
        return bytes;
    }
}
