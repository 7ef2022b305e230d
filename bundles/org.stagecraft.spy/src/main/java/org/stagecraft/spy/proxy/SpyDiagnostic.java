package org.stagecraft.spy.proxy;

import org.stagecraft.player.wire.Direction;

/**
 * Something the spy could not make sense of, published so tools can show it: bytes that are not
 * a message, a payload that does not fit its layout, bytes the observer had to drop.
 */
public record SpyDiagnostic(ConnectionInfo connection, Direction dir, long streamOffset, String text) {
    @Override
    public String toString() {
        return "connection " + connection.id() + " (port " + connection.port() + ", " + dir.label() + ") offset "
                + streamOffset + ": " + text;
    }
}
