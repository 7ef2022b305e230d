package org.stagecraft.streams;

/**
 * Receives the messages of a {@link Subscription}, one at a time (never concurrently for one
 * subscription), in publish order within a stream. An exception thrown here is counted in
 * {@link Subscription#failures()} and delivery continues.
 */
@FunctionalInterface
public interface StreamConsumer {
    void accept(StreamMessage m);
}
