package org.stagecraft.foxglove.live;

import java.time.Duration;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import java.util.function.Function;

import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.spy.proxy.SpyDiagnostic;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * Feeds a {@link FoxgloveSink} (the live server) from a stream bus: one lossless, bounded subscription
 * to every stream, whose consumer runs the converter (e.g. {@code FoxgloveScene::new}, then its
 * {@code accept}). The bus never calls a consumer concurrently with itself, so the converter needs no
 * locking; and it never makes the publisher (the spy) wait: when the converter falls behind by more
 * than {@code capacity} messages, the bus drops and counts them ({@link #dropped()}).
 *
 * <p>When a {@link ConnectionEnded} comes (see {@link EndOfConnections}), the channels that only that
 * connection fed are unadvertised; they are advertised again if messages come back.
 */
public final class BusRelay implements AutoCloseable {
    /** Messages that may wait for the converter: a few seconds of a busy multi-robot session. */
    public static final int DEFAULT_CAPACITY = 16_384;

    private final StreamBus bus;
    private final long publishedBefore;
    private final Subscription subscription;

    private BusRelay(StreamBus bus, long publishedBefore, Subscription subscription) {
        this.bus = bus;
        this.publishedBefore = publishedBefore;
        this.subscription = subscription;
    }

    /**
     * @param converter given the sink, returns what to call with each bus message
     */
    public static BusRelay start(StreamBus bus, FoxgloveSink sink,
            Function<FoxgloveSink, Consumer<StreamMessage>> converter, int capacity) {
        LiveChannels channels = new LiveChannels(sink);
        Consumer<StreamMessage> convert = converter.apply(channels);
        return new BusRelay(bus, bus.published(), bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(capacity), m -> {
            switch (m.payload()) {
                case ConnectionEnded end -> channels.connectionEnded(end.connection().id());
                case SpyMessage s -> convert(channels, s.connection().id(), convert, m);
                case SpyDiagnostic d -> convert(channels, d.connection().id(), convert, m);
                case null, default -> convert(channels, LiveChannels.NO_CONNECTION, convert, m);
            }
        }));
    }

    private static void convert(LiveChannels channels, int connection, Consumer<StreamMessage> convert, StreamMessage m) {
        channels.converting(connection);
        convert.accept(m);
    }

    /**
     * Once the publisher has stopped (the spy closed, its pipeline drained): waits until the converter
     * has taken every message published since the relay started, so that closing loses none.
     *
     * @return whether it got there within {@code timeout}
     */
    public boolean awaitIdle(Duration timeout) {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (subscription.delivered() + subscription.dropped() < bus.published() - publishedBefore) {
            if (System.nanoTime() > deadline || subscription.isClosed()) {
                return false;
            }
            LockSupport.parkNanos(1_000_000L); // the bus has no "drained" event; a stop is a rare moment
        }
        return true;
    }

    /** Bus messages converted so far. */
    public long delivered() {
        return subscription.delivered();
    }

    /** Bus messages the converter never saw because it was behind. */
    public long dropped() {
        return subscription.dropped();
    }

    /** Messages the converter failed on (it threw). */
    public long failures() {
        return subscription.failures();
    }

    @Override
    public void close() {
        subscription.close();
    }
}
