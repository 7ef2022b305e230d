package org.stagecraft.player.session;

import org.stagecraft.player.wire.WireEvent;

/**
 * A framed event of an observed session, stamped with the receive time of the chunk that
 * completed it.
 */
public record SessionEvent(double t, StreamId stream, WireEvent event) {
}
