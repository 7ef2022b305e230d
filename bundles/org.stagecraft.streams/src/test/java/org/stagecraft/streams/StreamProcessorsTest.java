package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.streams.Streams.SONAR;
import static org.stagecraft.streams.Streams.data;
import static org.stagecraft.streams.Streams.msg;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

/** User-derived streams: a processor averaging a 16-value sonar ring publishes type 128. */
class StreamProcessorsTest {
    private final StreamBus bus = new StreamBus(Runnable::run);
    private final StreamProcessors processors = new StreamProcessors(bus);

    private static double[] ring(double first) {
        double[] r = new double[16];
        for (int i = 0; i < r.length; i++) {
            r[i] = first + i;
        }
        return r;
    }

    @Test
    void derivedStreamIsSubscribableLikeAWireStream() {
        List<StreamMessage> averages = new ArrayList<>();
        List<StreamKey> newStreams = new ArrayList<>();
        bus.onNewStream(newStreams::add);
        // subscribed before the processor even runs: the derived stream does not exist yet
        Subscription s = bus.subscribe(StreamPattern.parse("type=128 dev=5"), DeliveryPolicy.lossless(16),
                averages::add);
        processors.start("sonar-average", new SonarRingAverage());

        StreamKey ranges = data(SONAR, 0, 1);
        bus.publish(new StreamMessage(ranges, 42L, ring(0)));    // 0..15 -> 7.5
        bus.publish(new StreamMessage(ranges, 43L, ring(1.0)));  // 1..16 -> 8.5
        bus.publish(msg(data(SONAR, 0, 2), "geometry, not ranges"));

        assertEquals(2, averages.size());
        StreamKey derived = ranges.withMessageType(128);
        assertEquals(new StreamMessage(derived, 42L, 7.5), averages.get(0));
        assertEquals(8.5, averages.get(1).payload());
        assertTrue(averages.get(0).key().isUserDefined());
        assertTrue(bus.streams().contains(derived));
        assertEquals(List.of(ranges, derived, data(SONAR, 0, 2)), newStreams);
        assertEquals(2, s.delivered());
        assertEquals(Set.of("sonar-average"), processors.ids());
    }

    @Test
    void processorsMayNotPublishWireTypes() {
        List<ProcessorContext> ctx = new ArrayList<>();
        processors.start("spoofer", ctx::add);
        StreamKey wire = data(SONAR, 0, 1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ctx.get(0).publish(msg(wire, 1.0)));
        assertTrue(e.getMessage().contains("spoofer") && e.getMessage().contains("128..255"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ctx.get(0).publish(msg(wire.withMessageType(127), 1.0)));
        ctx.get(0).publish(msg(wire.withMessageType(255), 1.0));
        assertEquals(1, bus.published());
        assertEquals("spoofer", ctx.get(0).processorId());
        assertTrue(ctx.get(0).bus() == bus);
    }

    @Test
    void stoppingAProcessorClosesItsSubscriptions() {
        List<Object> averages = new ArrayList<>();
        bus.subscribe(StreamPattern.any().messageType(128), DeliveryPolicy.latestValue(), m -> averages.add(m.payload()));
        boolean[] stopped = {false};
        processors.start("sonar-average", new StreamProcessor() {
            private final SonarRingAverage inner = new SonarRingAverage();

            @Override
            public void start(ProcessorContext c) {
                inner.start(c);
            }

            @Override
            public void stop() {
                stopped[0] = true;
            }
        });
        assertEquals(2, bus.subscriptionCount());
        bus.publish(msg(data(SONAR, 0, 1), ring(0)));
        processors.stopAll();
        assertTrue(stopped[0]);
        assertEquals(1, bus.subscriptionCount());
        bus.publish(msg(data(SONAR, 0, 1), ring(100)));
        assertEquals(List.of(7.5), averages);
        assertTrue(processors.ids().isEmpty());
    }

    @Test
    void duplicateIdsAndFailingStartsAreRejected() {
        processors.start("a", c -> { });
        assertThrows(IllegalArgumentException.class, () -> processors.start("a", c -> { }));
        IllegalStateException boom = assertThrows(IllegalStateException.class, () -> processors.start("b", c -> {
            c.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> { });
            throw new IllegalStateException("cannot start");
        }));
        assertEquals("cannot start", boom.getMessage());
        assertEquals(0, bus.subscriptionCount(), "the failed processor's subscription is closed");
        assertEquals(Set.of("a"), processors.ids());
        assertTrue(processors.stop("a"));
        assertTrue(!processors.stop("a"));
    }

    @Test
    void aThrowingStopDoesNotKeepOthersRunning() {
        processors.start("first", c -> c.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> { }));
        processors.start("bad-stop", new StreamProcessor() {
            @Override
            public void start(ProcessorContext c) {
                c.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> { });
            }

            @Override
            public void stop() {
                throw new IllegalStateException("stop bug");
            }
        });
        assertEquals(2, bus.subscriptionCount());
        processors.stopAll();
        assertEquals(0, bus.subscriptionCount());
    }

    @Test
    void serviceLoaderFindsProcessorsOnTheClassPath() {
        List<StreamProcessor> found = StreamProcessors.serviceLoaded();
        assertEquals(1, found.stream().filter(p -> p instanceof SonarRingAverage).count(), found.toString());
        List<Object> averages = new ArrayList<>();
        bus.subscribe(StreamPattern.parse("type=128"), DeliveryPolicy.latestValue(), m -> averages.add(m.payload()));
        for (StreamProcessor p : found) {
            processors.start(p.getClass().getName(), p);
        }
        bus.publish(msg(data(SONAR, 0, 1), ring(2)));
        assertEquals(List.of(9.5), averages);
    }
}
