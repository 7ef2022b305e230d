package org.stagecraft.streams;

import java.util.Set;

/**
 * Receives the messages of a {@link Subscription}, one at a time (never concurrently for one
 * subscription), in publish order within a stream. An exception thrown here is counted in
 * {@link Subscription#failures()} and delivery continues.
 */
@FunctionalInterface
public interface StreamConsumer {
    void accept(StreamMessage m);

    /**
     * Told, in order with the messages, that the bus released {@code streams} (those of the closed
     * connection at {@code address} that this subscription's pattern matches): no message of them is
     * delivered after this unless the stream starts again. Nothing by default — a view keeps showing
     * what it has; a forwarder releases them on its own bus. Called like {@link #accept}, never
     * concurrently with it.
     */
    default void released(String address, Set<StreamKey> streams) {
    }
}
