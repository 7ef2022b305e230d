package org.stagecraft.streams;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.TimeUnit;

/** Test helpers: keys, messages, waiting with timeouts (never sleeping). */
final class Streams {
    static final String ROBOT = "127.0.0.1:40312";
    static final String PLAYER = "127.0.0.1:6665";
    static final int DATA = 1;
    static final int SONAR = 5;
    static final int LASER = 6;

    private Streams() {
    }

    /** Player -> robot program DATA of the given device. */
    static StreamKey data(int device, int index, int subtype) {
        return new StreamKey(PLAYER, ROBOT, DATA, device, index, subtype);
    }

    static StreamMessage msg(StreamKey key, Object payload) {
        return new StreamMessage(key, System.currentTimeMillis() * 1_000_000L, payload);
    }

    static void await(CountDownLatch latch) {
        try {
            assertTrue(latch.await(10, TimeUnit.SECONDS), "timed out waiting (10 s)");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail(e);
        }
    }

    /** Returns once every task submitted to the single-threaded {@code executor} before this call has run. */
    static void flush(ExecutorService executor) {
        try {
            executor.submit(() -> { }).get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            fail("executor did not drain", e);
        }
    }

    /** A consumer that blocks in its first call until released. */
    static final class Gate {
        final CountDownLatch entered = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);

        void pass() {
            if (entered.getCount() > 0) {
                entered.countDown();
                try {
                    if (!release.await(30, TimeUnit.SECONDS)) {
                        throw new IllegalStateException("gate never released");
                    }
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }
    }
}
