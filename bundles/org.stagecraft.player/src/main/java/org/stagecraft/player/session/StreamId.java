package org.stagecraft.player.session;

import org.stagecraft.player.wire.Direction;

/**
 * One direction of one observed connection.
 *
 * @param conn connection number, in accept order
 * @param port the port the robot program connected to
 * @param dir  which way the bytes flow
 */
public record StreamId(int conn, int port, Direction dir) {
    @Override
    public String toString() {
        return "connection " + conn + " (port " + port + ", " + dir.label() + ")";
    }
}
