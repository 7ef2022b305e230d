package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.streams.Streams.LASER;
import static org.stagecraft.streams.Streams.SONAR;
import static org.stagecraft.streams.Streams.data;
import static org.stagecraft.streams.Streams.msg;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

import org.junit.jupiter.api.Test;

/** Routing, stream discovery, failures and closing, on a same-thread bus (deterministic). */
class StreamBusTest {
    private final StreamBus bus = new StreamBus(Runnable::run);

    @Test
    void subscriberBeforeTheStreamExistsGetsItsMessages() {
        List<Object> sonar = new ArrayList<>();
        Subscription s = bus.subscribe(StreamPattern.any().deviceType(SONAR), DeliveryPolicy.latestValue(),
                m -> sonar.add(m.payload()));
        assertTrue(bus.streams().isEmpty());

        bus.publish(msg(data(SONAR, 0, 1), "ranges-1"));
        bus.publish(msg(data(LASER, 0, 1), "scan"));
        bus.publish(msg(data(SONAR, 0, 2), "geom"));
        bus.publish(msg(data(SONAR, 0, 1), "ranges-2"));

        assertEquals(List.of("ranges-1", "geom", "ranges-2"), sonar);
        assertEquals(3, s.delivered());
        assertEquals(0, s.dropped());
        assertEquals(4, bus.published());
        assertEquals(Set.of(data(SONAR, 0, 1), data(LASER, 0, 1), data(SONAR, 0, 2)), bus.streams());
    }

    @Test
    void publishAllDeliversInOrderWithOneDrainTaskPerSubscription() {
        List<Runnable> tasks = new ArrayList<>();
        StreamBus batched = new StreamBus(tasks::add); // runs nothing until the test says so
        List<Object> sonar = new ArrayList<>();
        List<Object> everything = new ArrayList<>();
        Subscription s = batched.subscribe(StreamPattern.any().deviceType(SONAR), DeliveryPolicy.lossless(8),
                m -> sonar.add(m.payload()));
        Subscription all = batched.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(3), m -> everything.add(m.payload()));
        List<Object> latest = new ArrayList<>();
        batched.subscribe(StreamPattern.any().deviceType(LASER), DeliveryPolicy.latestValue(), m -> latest.add(m.payload()));

        batched.publishAll(List.of(msg(data(SONAR, 0, 1), "s1"), msg(data(LASER, 0, 1), "l1"),
                msg(data(SONAR, 0, 1), "s2"), msg(data(LASER, 0, 1), "l2")));

        assertEquals(3, tasks.size(), "one drain task per subscription that got messages, not one per message");
        tasks.forEach(Runnable::run);
        assertEquals(List.of("s1", "s2"), sonar);
        assertEquals(List.of("s1", "l1", "s2"), everything, "in publish order, up to the buffer's capacity");
        assertEquals(1, all.dropped(), "the message over the lossless capacity is counted");
        assertEquals(List.of("l2"), latest, "latest-value: the newer laser message replaced the older one");
        assertEquals(4, batched.published());
        assertEquals(2, s.delivered());
        assertEquals(Set.of(data(SONAR, 0, 1), data(LASER, 0, 1)), batched.streams());

        tasks.clear();
        batched.publishAll(List.of());
        assertTrue(tasks.isEmpty(), "nothing published, nothing scheduled");
    }

    @Test
    void lateSubscriberGetsLaterMessagesOfExistingStreams() {
        bus.publish(msg(data(LASER, 0, 1), "early"));
        List<Object> got = new ArrayList<>();
        bus.subscribe(StreamPattern.parse("dev=6"), DeliveryPolicy.lossless(8), m -> got.add(m.payload()));
        bus.publish(msg(data(LASER, 0, 1), "late"));
        assertEquals(List.of("late"), got); // the cached route for the key was invalidated by subscribe
    }

    @Test
    void everyMatchingSubscriptionGetsTheMessage() {
        List<String> got = new ArrayList<>();
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> got.add("any"));
        bus.subscribe(StreamPattern.parse("dst=*:40312 dev=5"), DeliveryPolicy.lossless(4), m -> got.add("sonar"));
        bus.subscribe(StreamPattern.parse("dst=*:6665"), DeliveryPolicy.lossless(4), m -> got.add("to-player"));
        bus.publish(msg(data(SONAR, 0, 1), 1));
        assertEquals(List.of("any", "sonar"), got);
    }

    @Test
    void newStreamIsAnnouncedOncePerKey() throws Exception {
        List<StreamKey> told = new ArrayList<>();
        AutoCloseable registration = bus.onNewStream(told::add);
        StreamKey a = data(SONAR, 0, 1);
        StreamKey b = data(LASER, 0, 1);
        bus.publish(msg(a, 1));
        bus.publish(msg(a, 2));
        bus.publish(msg(b, 3));
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> { }); // invalidates the route cache
        bus.publish(msg(a, 4));
        bus.publish(msg(b, 5));
        assertEquals(List.of(a, b), told);

        List<StreamKey> all = new ArrayList<>();
        bus.onNewStream(all::add, true);
        assertEquals(Set.of(a, b), Set.copyOf(all));

        registration.close();
        StreamKey c = data(SONAR, 1, 1);
        bus.publish(msg(c, 6));
        assertEquals(List.of(a, b), told); // closed registration hears nothing more
        assertEquals(3, all.size());
        assertEquals(c, all.get(2));
    }

    @Test
    void aThrowingListenerIsCountedAndOthersAreStillTold() {
        List<StreamKey> told = new ArrayList<>();
        bus.onNewStream(k -> {
            throw new IllegalStateException("listener bug");
        });
        bus.onNewStream(told::add);
        bus.publish(msg(data(SONAR, 0, 1), 1));
        assertEquals(1, told.size());
        assertEquals(1, bus.listenerFailures());
    }

    @Test
    void aThrowingConsumerKeepsGettingMessagesAndOthersAreUnaffected() {
        List<Object> flaky = new ArrayList<>();
        List<Object> healthy = new ArrayList<>();
        Subscription bad = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(100), m -> {
            flaky.add(m.payload());
            if ((Integer) m.payload() % 2 == 0) {
                throw new IllegalStateException("consumer bug at " + m.payload());
            }
        });
        Subscription good = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(100),
                m -> healthy.add(m.payload()));
        for (int i = 0; i < 10; i++) {
            bus.publish(msg(data(SONAR, 0, 1), i));
        }
        List<Object> expected = List.of(0, 1, 2, 3, 4, 5, 6, 7, 8, 9);
        assertEquals(expected, flaky);
        assertEquals(expected, healthy);
        assertEquals(5, bad.failures());
        assertEquals(10, bad.delivered());
        assertEquals("consumer bug at 8", bad.lastFailure().getMessage());
        assertEquals(0, good.failures());
        assertEquals(10, good.delivered());
    }

    @Test
    void closingASubscriptionStopsItsDeliveryOnly() {
        List<Object> closed = new ArrayList<>();
        List<Object> open = new ArrayList<>();
        Subscription s = bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> closed.add(m.payload()));
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> open.add(m.payload()));
        bus.publish(msg(data(SONAR, 0, 1), 1));
        s.close();
        s.close(); // idempotent
        assertTrue(s.isClosed());
        assertEquals(1, bus.subscriptionCount());
        bus.publish(msg(data(SONAR, 0, 1), 2));
        bus.publish(msg(data(LASER, 0, 1), 3));
        assertEquals(List.of(1), closed);
        assertEquals(1, s.delivered());
        assertEquals(List.of(1, 2, 3), open);
    }

    @Test
    void closingTheBusStopsAllDelivery() {
        List<Object> got = new ArrayList<>();
        Subscription s = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(10), m -> got.add(m.payload()));
        List<StreamKey> told = new ArrayList<>();
        bus.onNewStream(told::add);
        bus.publish(msg(data(SONAR, 0, 1), 1));
        bus.close();
        bus.close(); // idempotent
        bus.publish(msg(data(SONAR, 0, 1), 2));
        bus.publish(msg(data(LASER, 0, 1), 3));
        assertEquals(List.of(1), got);
        assertTrue(s.isClosed());
        assertEquals(1, told.size());
        assertEquals(1, bus.published());
        assertThrows(IllegalStateException.class,
                () -> bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> { }));
    }

    @Test
    void aConsumerMayPublishAndSubscribeFromWithinDelivery() {
        List<Object> derived = new CopyOnWriteArrayList<>();
        bus.subscribe(StreamPattern.any().messageType(1), DeliveryPolicy.lossless(10),
                m -> bus.publish(new StreamMessage(m.key().withMessageType(200), m.timeNanos(), "d" + m.payload())));
        bus.subscribe(StreamPattern.any().messageType(200), DeliveryPolicy.lossless(10), m -> derived.add(m.payload()));
        // a subscriber that matches its own output does not recurse without end
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(10), m -> { });
        bus.publish(msg(data(SONAR, 0, 1), 1));
        bus.publish(msg(data(SONAR, 0, 1), 2));
        assertEquals(List.of("d1", "d2"), derived);
        assertEquals(4, bus.published());
    }
}
