package org.stagecraft.core.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.Subscription;

/**
 * A Robot Session's bus forwarded to the workbench bus: when the session's spy releases the streams of
 * a closed connection, the workbench bus releases them too, after their last forwarded message
 * (issue 17: a workbench open for days with short-lived robot programs stays flat).
 */
class WorkbenchBusTest {
    @Test
    void theStreamsOfAClosedConnectionAreReleasedOnTheWorkbenchBusToo() throws InterruptedException {
        String client = "127.0.0.1:" + (40000 + (int) (ProcessHandle.current().pid() % 20000)); // not another test's
        List<StreamKey> keys = List.of(new StreamKey("127.0.0.1:6665", client, 1, 4, 0, 1),
                new StreamKey(client, "127.0.0.1:6665", 3, 4, 0, 1), new StreamKey("127.0.0.1:6665", client, 1, 6, 0, 1));
        StreamBus workbench = WorkbenchBus.get();
        CountDownLatch released = new CountDownLatch(1);
        AtomicReference<Set<StreamKey>> releasedKeys = new AtomicReference<>();
        StreamBus.Registration r = workbench.onRelease((address, streams) -> {
            if (address.equals(client)) {
                releasedKeys.set(streams);
                released.countDown();
            }
        });
        try (StreamBus session = new StreamBus()) {
            Subscription forward = WorkbenchBus.forward(session);
            for (StreamKey k : keys) {
                session.publish(new StreamMessage(k, 1, "last"));
            }
            session.release(client); // the connection closed
            assertTrue(released.await(30, TimeUnit.SECONDS), "the workbench bus released the connection's streams");
            assertEquals(Set.copyOf(keys), releasedKeys.get());
            assertTrue(workbench.streams().stream().noneMatch(k -> k.source().equals(client) || k.destination().equals(client)),
                    workbench.streams().toString());
            assertEquals(keys.size(), forward.delivered(), "every message was forwarded before the release");
            forward.close();
        } finally {
            r.close();
        }
    }
}
