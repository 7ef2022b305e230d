package org.stagecraft.streams;

/**
 * Derives streams from other streams, e.g. the average of a sonar ring. {@link #start} subscribes
 * through the context and publishes derived messages with user-defined message types
 * ({@value StreamTypes#USER_MIN}..{@value StreamTypes#USER_MAX}); a derived stream is subscribable like
 * any wire stream. Subscriptions made through the context are closed when the processor stops.
 *
 * <p>
 * Registered in Eclipse through the {@code org.stagecraft.core.streamProcessors} extension point, in
 * plain Java through {@link java.util.ServiceLoader}
 * ({@code META-INF/services/org.stagecraft.streams.StreamProcessor}); either way the class needs a
 * public no-argument constructor.
 */
public interface StreamProcessor {
    void start(ProcessorContext ctx);

    /** Releases what {@link #start} acquired beyond its subscriptions (those are closed for it). */
    default void stop() {
    }
}
