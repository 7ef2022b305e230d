package org.stagecraft.streams;

/** What a {@link StreamProcessor} sees of the bus it runs on. */
public interface ProcessorContext {
    StreamBus bus();

    /** Subscribes on the bus; the subscription is closed when the processor stops. */
    Subscription subscribe(StreamPattern p, DeliveryPolicy d, StreamConsumer c);

    /**
     * Publishes a derived message.
     *
     * @throws IllegalArgumentException if its message type is below {@value StreamTypes#USER_MIN}
     *                                  (processors may not impersonate wire streams)
     */
    void publish(StreamMessage derived);

    String processorId();
}
