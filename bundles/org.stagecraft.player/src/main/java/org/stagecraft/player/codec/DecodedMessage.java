package org.stagecraft.player.codec;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.MessageHeader;

/**
 * A Player message after decoding: its header, its body (typed, {@link EmptyBody} or
 * {@link RawBody}) and, when a decoder refused the payload, the problem.
 */
public record DecodedMessage(MessageHeader header, MessageBody body, @Nullable DecodeProblem problem) {

    public boolean hasProblem() {
        return problem != null;
    }
}
