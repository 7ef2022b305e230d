package org.stagecraft.foxglove;

/**
 * Where Foxglove-shaped messages go: an MCAP export or the live WebSocket server. A channel is
 * advertised once, before its first message.
 */
public interface FoxgloveSink {

    void advertise(FoxgloveChannel channel);

    /**
     * @param logTimeNanos     when the message was captured, nanoseconds since the epoch
     * @param publishTimeNanos when its source produced it, nanoseconds since the epoch
     * @param json             the message, UTF-8 JSON valid against the channel's schema
     */
    void publish(FoxgloveChannel channel, long logTimeNanos, long publishTimeNanos, byte[] json);

    /**
     * The channel's stream has ended (its robot disconnected): the live server tells its viewers; a file
     * has nothing to do. A channel may be advertised again later.
     */
    default void unadvertise(FoxgloveChannel channel) {
    }
}
