package org.stagecraft.scene;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;

/**
 * Publishes recorded messages on a bus at their recorded pace, optionally over and over: a recorded
 * session shown live in the views (demonstrations, screenshots) without Player or sockets.
 */
public final class TraceReplay {
    private TraceReplay() {
    }

    /** Starts replaying on a virtual thread; interrupt it to stop. */
    public static Thread start(List<StreamMessage> messages, StreamBus bus, boolean loop) {
        return Thread.ofVirtual().name("stagecraft-trace-replay").start(() -> {
            do {
                if (!playOnce(messages, bus)) {
                    return;
                }
            } while (loop && !Thread.currentThread().isInterrupted());
        });
    }

    /** @return false if interrupted or the bus closed */
    static boolean playOnce(List<StreamMessage> messages, StreamBus bus) {
        if (messages.isEmpty()) {
            return false;
        }
        long t0 = messages.get(0).timeNanos(), start = System.nanoTime();
        for (StreamMessage m : messages) {
            long due = start + (m.timeNanos() - t0);
            // pacing, not synchronisation: the recorded gaps between messages are the point
            for (long wait = due - System.nanoTime(); wait > 0; wait = due - System.nanoTime()) {
                LockSupport.parkNanos(Math.min(wait, TimeUnit.MILLISECONDS.toNanos(100)));
                if (Thread.currentThread().isInterrupted()) {
                    return false;
                }
            }
            if (bus.isClosed()) {
                return false;
            }
            bus.publish(new StreamMessage(m.key(), System.nanoTime(), m.payload()));
        }
        return true;
    }
}
