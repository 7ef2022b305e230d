package org.stagecraft.foxglove.live;

import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A bus payload that tells the live view a robot program's connection is over, published after the
 * connection's last message (by the spy's recorder hook, see {@link EndOfConnections}). The converter never
 * sees it: {@link BusRelay} takes it to unadvertise the channels only that connection fed.
 */
public record ConnectionEnded(ConnectionInfo connection) {
}
