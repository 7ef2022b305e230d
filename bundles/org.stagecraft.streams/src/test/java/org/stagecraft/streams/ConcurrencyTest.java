package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.streams.Streams.await;
import static org.stagecraft.streams.Streams.data;
import static org.stagecraft.streams.Streams.msg;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The bus with its own (virtual) delivery threads: a stuck consumer never holds up the publisher. */
@Timeout(60)
class ConcurrencyTest {

    @Test
    void publisherIsNotBlockedByAStuckConsumer() {
        try (StreamBus bus = new StreamBus()) {
            Streams.Gate losslessGate = new Streams.Gate();
            Streams.Gate latestGate = new Streams.Gate();
            AtomicReference<Object> lastSeen = new AtomicReference<>();
            CountDownLatch gotNewest = new CountDownLatch(1);
            Subscription logger = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1000),
                    m -> losslessGate.pass());
            Subscription view = bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> {
                latestGate.pass();
                lastSeen.set(m.payload());
                if (Integer.valueOf(100_000).equals(m.payload())) {
                    gotNewest.countDown();
                }
            });
            StreamKey key = data(Streams.SONAR, 0, 1);
            bus.publish(msg(key, 0));
            await(losslessGate.entered);
            await(latestGate.entered);

            for (int i = 1; i <= 100_000; i++) { // returns although both consumers are stuck in message 0
                bus.publish(msg(key, i));
            }

            assertEquals(100_001, bus.published());
            assertEquals(0, logger.delivered());
            assertEquals(100_000 - 1000, logger.dropped());
            assertEquals(1000, ((BusSubscription) logger).pending());
            assertEquals(0, view.delivered());
            assertEquals(100_000 - 1, view.dropped());
            assertEquals(1, ((BusSubscription) view).pending());

            latestGate.release.countDown();
            await(gotNewest);
            assertEquals(100_000, lastSeen.get());
            losslessGate.release.countDown();
        }
    }

    @Test
    void concurrentPublishersCountsAddUp() throws Exception {
        int threads = 8;
        int perThread = 20_000;
        try (StreamBus bus = new StreamBus()) {
            CountDownLatch allDelivered = new CountDownLatch(threads * perThread);
            ConcurrentHashMap<StreamKey, AtomicInteger> lastPerStream = new ConcurrentHashMap<>();
            AtomicInteger outOfOrder = new AtomicInteger();
            Subscription all = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(threads * perThread), m -> {
                int seq = (Integer) m.payload();
                int previous = lastPerStream.computeIfAbsent(m.key(), k -> new AtomicInteger(-1)).getAndSet(seq);
                if (seq != previous + 1) {
                    outOfOrder.incrementAndGet();
                }
                allDelivered.countDown();
            });
            Subscription latest = bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> { });
            Subscription evens = bus.subscribe(StreamPattern.parse("index=0"), DeliveryPolicy.lossless(10), m -> { });

            CountDownLatch start = new CountDownLatch(1);
            List<Thread> publishers = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                StreamKey key = data(Streams.SONAR, t, 1); // one stream per publisher: order is defined per stream
                publishers.add(Thread.ofPlatform().start(() -> {
                    await(start);
                    for (int i = 0; i < perThread; i++) {
                        bus.publish(msg(key, i));
                    }
                }));
            }
            start.countDown();
            for (Thread p : publishers) {
                p.join();
            }
            await(allDelivered);

            assertEquals((long) threads * perThread, bus.published());
            assertEquals(0, all.dropped());
            assertEquals(0, outOfOrder.get(), "within a stream, delivery order is publish order");
            assertEquals(threads, bus.streams().size());
            assertEquals(threads, lastPerStream.size());
            for (AtomicInteger last : lastPerStream.values()) {
                assertEquals(perThread - 1, last.get());
            }
            // the latest-value subscriber: everything is delivered or counted as superseded, except what is
            // still pending (at most one per stream); the drain may still be running, so bound it
            long seen = latest.delivered() + latest.dropped();
            assertTrue(seen >= (long) threads * perThread - threads - 1 && seen <= (long) threads * perThread, "" + seen);
            assertTrue(evens.dropped() <= perThread && evens.dropped() + evens.delivered() <= perThread);
        }
    }

    @Test
    void subscribingWhilePublishingNeverLosesTheNewSubscriptionFromTheCache() throws Exception {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            StreamKey key = data(Streams.LASER, 0, 1);
            AtomicInteger stop = new AtomicInteger();
            Thread publisher = Thread.ofPlatform().start(() -> {
                while (stop.get() == 0) {
                    bus.publish(msg(key, 1));
                }
            });
            try {
                for (int i = 0; i < 200; i++) {
                    CountDownLatch got = new CountDownLatch(1);
                    Subscription s = bus.subscribe(StreamPattern.any().deviceType(Streams.LASER),
                            DeliveryPolicy.latestValue(), m -> got.countDown());
                    await(got); // a stale cached route would starve this subscription forever
                    s.close();
                }
            } finally {
                stop.set(1);
                publisher.join();
            }
            assertEquals(0, bus.subscriptionCount());
        }
    }
}
