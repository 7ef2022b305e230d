package org.stagecraft.spy.breakpoint;

import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * What a robot data breakpoint tests on a message from Player. The spy knows bytes and headers only; the
 * field language that reads decoded fields lives above it (org.stagecraft.replay.fields.StreamCondition).
 * Called on relay threads: implementations are thread-safe and quick.
 */
public interface MessageCondition {

    /**
     * A message satisfied the condition.
     *
     * @param why            for people, e.g. "laser:0 min(ranges) = 0.287 m < 0.3 m"
     * @param decidingFields the message's fields that decided it, as paths ({@code ranges[147]}), for a
     *                       view to mark; may be empty
     */
    record Satisfied(String why, List<String> decidingFields) {
        public Satisfied {
            decidingFields = List.copyOf(decidingFields);
        }
    }

    /**
     * Whether messages with this header on this connection are ever tested (device, message type). Only
     * those are kept whole until tested; every other message passes as it comes.
     */
    boolean watches(ConnectionInfo connection, MessageHeader header);

    /**
     * Tests one whole message that {@link #watches} accepted.
     *
     * @param payload the message's payload (after the 40-byte header)
     * @return why it holds and what decided it, or null when it does not
     */
    @Nullable Satisfied test(MessageHeader header, byte[] payload);

    /** The condition as the user wrote it. */
    String text();
}
