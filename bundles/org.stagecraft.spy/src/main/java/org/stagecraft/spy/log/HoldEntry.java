package org.stagecraft.spy.log;

/**
 * Something Stagecraft itself did to a robot program's stream while a robot hold was on (see
 * docs/debugging-robots.md): bytes it injected towards Player, program bytes it held back, or the
 * hold switching on or off. These entries live on the log's own {@code /stagecraft/hold} channel, apart
 * from the wire channels, which keep recording exactly what the program sent; with both,
 * {@link SpyLogReader#upstreamBytes} rebuilds what Player received.
 *
 * @param conn           the connection, 0 for {@link Action#HOLD_ON}/{@link Action#HOLD_OFF} (they concern the spy)
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
        HOLD_OFF
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
