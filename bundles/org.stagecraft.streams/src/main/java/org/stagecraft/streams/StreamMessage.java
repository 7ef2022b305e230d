package org.stagecraft.streams;

import java.util.Objects;

/**
 * One message on a stream.
 *
 * @param key       the stream
 * @param timeNanos receive time, nanoseconds since the epoch
 * @param payload   the decoded body (any object, typically immutable; may be {@code null})
 */
public record StreamMessage(StreamKey key, long timeNanos, Object payload) {
    public StreamMessage {
        Objects.requireNonNull(key, "key");
    }
}
