package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.stagecraft.streams.Streams.await;
import static org.stagecraft.streams.Streams.msg;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Issue 17 item 4: the streams of a closed connection are released, so a bus serving short-lived
 * connections for days stays flat, and what subscribers already have (or have buffered) stays theirs.
 */
@Timeout(60)
class StreamReleaseTest {
    private static final String PLAYER = "127.0.0.1:6665";
    /** Message, device, index and subtype of the ~20 streams one short robot connection makes. */
    private static final int[][] STREAMS = {
            { 2, 1, 0, 1 }, { 3, 1, 0, 1 }, { 4, 1, 0, 1 }, { 3, 4, 0, 1 }, { 4, 4, 0, 1 }, { 3, 5, 0, 1 },
            { 4, 5, 0, 1 }, { 3, 4, 0, 2 }, { 4, 4, 0, 2 }, { 1, 4, 0, 1 }, { 1, 5, 0, 1 }, { 1, 62, 0, 1 },
            { 3, 62, 0, 4 }, { 4, 62, 0, 4 }, { 2, 4, 0, 1 }, { 0, 0, 0, 0 } };

    private static String client(int i) {
        return "127.0.0.1:" + (1024 + i % 60000);
    }

    /** Both directions of one connection's streams, as the spy keys them. */
    private static List<StreamKey> connection(String client) {
        List<StreamKey> keys = new ArrayList<>();
        for (int[] s : STREAMS) {
            keys.add(new StreamKey(client, PLAYER, s[0], s[1], s[2], s[3]));
            keys.add(new StreamKey(PLAYER, client, s[0], s[1], s[2], s[3]));
        }
        return keys;
    }

    @Test
    void thousandsOfShortConnectionsLeaveTheBusAtItsBaseline() {
        StreamBus bus = new StreamBus(Runnable::run);
        List<StreamKey> told = new ArrayList<>();
        bus.onNewStream(told::add);
        Map<StreamKey, Object> view = new ConcurrentHashMap<>();
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> view.put(m.key(), m.payload()));
        bus.subscribe(StreamPattern.any().messageType(1), DeliveryPolicy.lossless(64), m -> { });
        // a long-lived stream that is not any connection's (e.g. the robot hold state)
        StreamKey hold = new StreamKey("stagecraft", "robot-hold", 200, 0, 0, 0);
        bus.publish(msg(hold, "on"));
        StreamBus.Footprint baseline = bus.footprint();
        assertEquals(new StreamBus.Footprint(1, 1, 2, 1), baseline);

        int connections = 5000;
        for (int i = 0; i < connections; i++) {
            String client = client(i);
            for (StreamKey k : connection(client)) {
                bus.publish(msg(k, i));
            }
            assertEquals(STREAMS.length * 2, bus.release(client));
        }
        assertEquals(baseline, bus.footprint(), "known streams, routes, address index and listener memory");
        assertEquals(Set.of(hold), bus.streams());
        assertEquals(connections * STREAMS.length * 2L, bus.released());
        assertEquals(1 + connections * STREAMS.length * 2, told.size(), "each stream was announced once");
        // the subscriber kept the last message of every stream it was shown, released or not
        assertEquals(Math.min(connections, 60000) * STREAMS.length * 2 + 1, view.size());
        assertEquals(connections - 1, view.get(connection(client(connections - 1)).get(0)));
    }

    @Test
    void releaseForgetsOnlyThatConnectionsStreams() {
        StreamBus bus = new StreamBus(Runnable::run);
        List<StreamKey> a = connection(client(1));
        List<StreamKey> b = connection(client(2));
        a.forEach(k -> bus.publish(msg(k, "a")));
        b.forEach(k -> bus.publish(msg(k, "b")));
        assertEquals(a.size(), bus.release(client(1)));
        assertEquals(Set.copyOf(b), bus.streams());
        assertEquals(0, bus.release(client(1)), "releasing twice releases nothing");
        assertEquals(0, bus.release("127.0.0.1:9"), "an address without streams");
        assertEquals(Set.copyOf(b), bus.streams());
        assertEquals(new StreamBus.Footprint(b.size(), b.size(), 2, 0), bus.footprint());
    }

    @Test
    void aReleasedStreamThatComesBackIsAnnouncedAndRoutedAgain() {
        StreamBus bus = new StreamBus(Runnable::run);
        List<StreamKey> told = new ArrayList<>();
        bus.onNewStream(told::add);
        List<Object> got = new ArrayList<>();
        StreamKey k = connection(client(7)).get(0);
        bus.subscribe(StreamPattern.any().source(client(7)), DeliveryPolicy.lossless(8), m -> got.add(m.payload()));
        bus.publish(msg(k, 1));
        bus.release(client(7));
        assertFalse(bus.streams().contains(k));
        bus.publish(msg(k, 2)); // the client port was reused by a new connection
        assertEquals(List.of(k, k), told);
        assertEquals(List.of(1, 2), got);
        assertTrue(bus.streams().contains(k));
    }

    @Test
    void aMessageStillBufferedForASlowViewIsDeliveredAfterTheRelease() {
        ExecutorService delivery = Executors.newSingleThreadExecutor();
        try (StreamBus bus = new StreamBus(delivery)) {
            Streams.Gate gate = new Streams.Gate();
            Map<StreamKey, Object> shown = new ConcurrentHashMap<>();
            StreamKey first = new StreamKey("x:1", "y:1", 1, 0, 0, 0);
            bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> {
                gate.pass();
                shown.put(m.key(), m.payload());
            });
            bus.publish(msg(first, "blocker"));
            await(gate.entered); // the view is busy (e.g. drawing) while the robot's last data arrives
            List<StreamKey> keys = connection(client(3));
            keys.forEach(k -> bus.publish(msg(k, "last")));
            bus.release(client(3)); // the connection closed
            assertTrue(bus.streams().equals(Set.of(first)));
            gate.release.countDown();
            Streams.flush(delivery);
            for (StreamKey k : keys) {
                assertEquals("last", shown.get(k), "the view keeps the last data of " + k);
            }
        } finally {
            delivery.shutdownNow();
        }
    }

    @Test
    void releaseListenersAreToldTheAddressAndItsStreams() {
        StreamBus bus = new StreamBus(Runnable::run);
        List<String> addresses = new CopyOnWriteArrayList<>();
        List<Set<StreamKey>> streams = new CopyOnWriteArrayList<>();
        StreamBus.Registration r = bus.onRelease((address, keys) -> {
            addresses.add(address);
            streams.add(keys);
        });
        List<StreamKey> keys = connection(client(5));
        keys.forEach(k -> bus.publish(msg(k, 0)));
        bus.release(client(5));
        bus.release(client(6)); // nothing to release: nobody is told
        assertEquals(List.of(client(5)), addresses);
        assertEquals(List.of(Set.copyOf(keys)), streams);
        r.close();
        keys.forEach(k -> bus.publish(msg(k, 0)));
        bus.release(client(5));
        assertEquals(1, addresses.size());
    }

    @Test
    void aForwarderReleasesOnItsOwnBusAfterTheLastForwardedMessage() {
        ExecutorService delivery = Executors.newSingleThreadExecutor();
        try (StreamBus source = new StreamBus(delivery); StreamBus target = new StreamBus(Runnable::run)) {
            Streams.Gate gate = new Streams.Gate();
            List<String> order = new CopyOnWriteArrayList<>();
            // the workbench's forwarder (WorkbenchBus.forward) in miniature, held up while messages queue
            Subscription forward = source.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1024), new StreamConsumer() {
                @Override
                public void accept(StreamMessage m) {
                    gate.pass();
                    target.publish(m);
                    order.add("message");
                }

                @Override
                public void released(String address, Set<StreamKey> streams) {
                    order.add("released " + streams.size());
                    target.release(address);
                }
            });
            List<StreamKey> keys = connection(client(4));
            keys.forEach(k -> source.publish(msg(k, 1)));
            await(gate.entered);
            source.release(client(4));
            assertTrue(source.streams().isEmpty());
            gate.release.countDown();
            Streams.flush(delivery);
            assertEquals(keys.size() + 1, order.size());
            assertEquals("released " + keys.size(), order.get(keys.size()), "the release comes after the messages");
            assertEquals(new StreamBus.Footprint(0, 0, 0, 0), target.footprint());
            assertEquals(keys.size(), forward.delivered());
            assertEquals(0, forward.dropped());
        } finally {
            delivery.shutdownNow();
        }
    }

    @Test
    void aBlockedViewThatIgnoresReleasesQueuesNoneOfThem() {
        ExecutorService delivery = Executors.newSingleThreadExecutor();
        try (StreamBus bus = new StreamBus(delivery)) {
            Streams.Gate gate = new Streams.Gate();
            Subscription view = bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> gate.pass());
            bus.publish(msg(new StreamKey("x:1", "y:1", 1, 0, 0, 0), "blocker"));
            await(gate.entered); // the view is stuck while a thousand connections come and go
            for (int i = 0; i < 1000; i++) {
                connection(client(i)).forEach(k -> bus.publish(msg(k, 0)));
                bus.release(client(i));
            }
            BusSubscription impl = (BusSubscription) view;
            assertEquals(0, impl.pendingReleases(), "a lambda consumer cannot act on releases: none is kept for it");
            assertEquals(connection(client(0)).size() * 1000, impl.pending() + view.dropped(),
                    "its buffered messages are still one per stream, the rest counted as dropped");
            gate.release.countDown();
            Streams.flush(delivery);
        } finally {
            delivery.shutdownNow();
        }
    }
}
