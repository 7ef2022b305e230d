package org.stagecraft.spy.proxy;

import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.wire.Direction;

/**
 * What the spy publishes on the stream bus for each Player message it saw: the decoded message
 * and where it was on the wire.
 *
 * @param streamOffset byte offset of the message's header in its connection's direction
 */
public record SpyMessage(ConnectionInfo connection, Direction dir, long streamOffset, DecodedMessage message) {
}
