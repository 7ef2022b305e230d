package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.streams.Streams.LASER;
import static org.stagecraft.streams.Streams.SONAR;
import static org.stagecraft.streams.Streams.await;
import static org.stagecraft.streams.Streams.data;
import static org.stagecraft.streams.Streams.flush;
import static org.stagecraft.streams.Streams.msg;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Latest-value and lossless delivery with a consumer that is blocked (on a latch) while the publisher
 * goes on. Delivery runs on one separate thread, so {@link Streams#flush} tells when it is done.
 */
@Timeout(60)
class DeliveryPolicyTest {
    private final ExecutorService delivery = Executors.newSingleThreadExecutor();
    private final StreamBus bus = new StreamBus(delivery);

    @AfterEach
    void shutdown() {
        bus.close();
        delivery.shutdownNow();
    }

    @Test
    void latestValueKeepsOnlyTheNewestPerStreamWhileTheConsumerIsBlocked() {
        Streams.Gate gate = new Streams.Gate();
        List<StreamMessage> got = new CopyOnWriteArrayList<>();
        Subscription s = bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> {
            gate.pass();
            got.add(m);
        });
        StreamKey sonar = data(SONAR, 0, 1);
        StreamKey laser = data(LASER, 0, 1);
        bus.publish(msg(sonar, 0));
        await(gate.entered); // the consumer now holds message 0 and is blocked

        for (int i = 1; i <= 1000; i++) {
            bus.publish(msg(sonar, i));
            bus.publish(msg(laser, -i));
        }
        BusSubscription impl = (BusSubscription) s;
        assertEquals(2, impl.pending(), "memory: one message per stream, whatever was published");
        assertEquals(2 * 999, s.dropped(), "superseded messages are counted as dropped");
        assertTrue(got.isEmpty());

        gate.release.countDown();
        flush(delivery);
        assertEquals(3, got.size(), got.toString());
        assertEquals(0, got.get(0).payload());
        List<Object> newest = new ArrayList<>();
        newest.add(got.get(1).payload());
        newest.add(got.get(2).payload());
        assertTrue(newest.containsAll(List.of(1000, -1000)), newest.toString());
        assertEquals(3, s.delivered());
        assertEquals(2 * 999, s.dropped());
        assertEquals(0, impl.pending());
        assertEquals(2001, s.delivered() + s.dropped(), "every published message is delivered or dropped");
    }

    @Test
    void losslessDeliversInOrderUpToCapacityAndCountsOverflow() {
        Streams.Gate gate = new Streams.Gate();
        List<Object> got = new CopyOnWriteArrayList<>();
        Subscription s = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(10), m -> {
            gate.pass();
            got.add(m.payload());
        });
        StreamKey key = data(SONAR, 0, 1);
        bus.publish(msg(key, 0));
        await(gate.entered);
        for (int i = 1; i <= 100; i++) {
            bus.publish(msg(key, i));
        }
        assertEquals(90, s.dropped(), "messages beyond capacity are dropped and counted");
        assertEquals(10, ((BusSubscription) s).pending());

        gate.release.countDown();
        flush(delivery);
        assertEquals(List.of(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10), got, "FIFO: the first ones that fitted, in order");
        assertEquals(11, s.delivered());
        assertEquals(90, s.dropped());

        bus.publish(msg(key, 101)); // room again after the drain
        flush(delivery);
        assertEquals(101, got.get(got.size() - 1));
        assertEquals(90, s.dropped());
    }

    @Test
    void losslessWithRoomLosesNothingAcrossBatches() {
        List<Object> got = new CopyOnWriteArrayList<>();
        Streams.Gate gate = new Streams.Gate();
        Subscription s = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(5000), m -> {
            gate.pass();
            got.add(m.payload());
        });
        StreamKey key = data(SONAR, 0, 1);
        bus.publish(msg(key, 0));
        await(gate.entered);
        for (int i = 1; i < 3000; i++) { // more than one drain batch
            bus.publish(msg(key, i));
        }
        gate.release.countDown();
        Streams.flush(delivery);
        // the drain task re-submits itself after each batch: flush until the count is stable
        for (int i = 0; i < 3000 / StreamBus.BATCH + 1; i++) {
            flush(delivery);
        }
        assertEquals(3000, got.size());
        for (int i = 0; i < 3000; i++) {
            assertEquals(i, got.get(i));
        }
        assertEquals(0, s.dropped());
    }

    @Test
    void aStuckConsumerDelaysOnlyItself() {
        Streams.Gate gate = new Streams.Gate();
        CountDownLatch fastGotAll = new CountDownLatch(50);
        Subscription stuck = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(8), m -> gate.pass());
        StreamBus other = new StreamBus(); // its own threads
        try {
            Subscription fast = other.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(100),
                    m -> fastGotAll.countDown());
            for (int i = 0; i < 50; i++) {
                StreamMessage m = msg(data(SONAR, 0, 1), i);
                bus.publish(m);
                other.publish(m);
            }
            await(fastGotAll);
            assertEquals(0, fast.dropped());
            assertFalse(stuck.delivered() > 0, "the stuck consumer is still in its first message");
        } finally {
            gate.release.countDown();
            other.close();
        }
    }

    @Test
    void closingWhileMessagesWaitDiscardsAndCountsThem() {
        Streams.Gate gate = new Streams.Gate();
        List<Object> got = new CopyOnWriteArrayList<>();
        Subscription s = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(100), m -> {
            gate.pass();
            got.add(m.payload());
        });
        StreamKey key = data(SONAR, 0, 1);
        bus.publish(msg(key, 0));
        await(gate.entered);
        for (int i = 1; i <= 20; i++) {
            bus.publish(msg(key, i));
        }
        s.close();
        gate.release.countDown();
        flush(delivery);
        assertEquals(List.of(0), got, "the delivery in progress finishes, nothing starts after close");
        assertEquals(20, s.dropped());
        assertEquals(1, s.delivered());
    }
}
