package org.stagecraft.spy.proxy;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.streams.StreamKey;

/**
 * The stream keys under which the spy publishes what it saw. Kept in one place because replay must
 * publish a logged message under exactly the key the live spy used, or views would not recognise it.
 */
public final class SpyStreams {
    /** Message type of the spy's diagnostics stream (Player's message types start at 1). */
    public static final int DIAGNOSTIC_TYPE = 0;

    private SpyStreams() {
    }

    /** The key of a Player message seen on a connection in the given direction. */
    public static StreamKey messageKey(ConnectionInfo c, Direction dir, MessageHeader h) {
        return key(c, dir, h.type(), h.interf(), h.index(), h.subtype());
    }

    /** The key of the diagnostics about one direction of a connection. */
    public static StreamKey diagnosticKey(ConnectionInfo c, Direction dir) {
        return key(c, dir, DIAGNOSTIC_TYPE, 0, 0, 0);
    }

    /** Client-to-server messages go from the robot program to the Player port it used, and back. */
    public static StreamKey key(ConnectionInfo c, Direction dir, int type, int interf, int index, int subtype) {
        return dir == Direction.CLIENT_TO_SERVER ? new StreamKey(c.client(), c.listen(), type, interf, index, subtype)
                : new StreamKey(c.listen(), c.client(), type, interf, index, subtype);
    }
}
