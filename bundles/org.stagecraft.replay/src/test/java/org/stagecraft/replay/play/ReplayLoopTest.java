package org.stagecraft.replay.play;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.replay.log.Logs;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/** A recorded session played over and over, as the workbench does for STAGECRAFT_REPLAY. */
class ReplayLoopTest {
    private SessionLog log;
    /** What one pass publishes: what the live spy published, in order. */
    private List<StreamMessage> onePass;
    private StreamBus bus;
    private final BlockingQueue<StreamMessage> published = new LinkedBlockingQueue<>();

    @BeforeEach
    void open() throws IOException {
        log = SessionLogs.open(Logs.trace(Logs.GT));
        onePass = Logs.all(log).stream().flatMap(m -> m.toStreamMessage().stream()).toList();
        bus = new StreamBus();
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 20), published::add);
    }

    @AfterEach
    void close() throws IOException {
        bus.close();
        log.close();
    }

    private StreamMessage next() throws InterruptedException {
        StreamMessage m = published.poll(30, TimeUnit.SECONDS);
        assertNotNull(m, "replay went on");
        return m;
    }

    @Test
    void atTheEndOfTheLogPlayStartsAgainFromTheStartWithTheSameMessages() throws Exception {
        try (Replayer r = new Replayer(log, bus, new ManualClock(false, 0))) {
            ReplayLoop loop = ReplayLoop.start(r);
            for (int pass = 0; pass < 3; pass++) {
                for (int i = 0; i < onePass.size(); i++) {
                    StreamMessage want = onePass.get(i), got = next();
                    assertEquals(want.key(), got.key(), "pass " + pass + ", message " + i);
                    assertEquals(want.timeNanos(), got.timeNanos(), "pass " + pass + ", message " + i);
                }
            }
            assertTrue(loop.restarts() >= 2, "restarted " + loop.restarts() + " times");
        }
    }

    @Test
    void aPauseBeforeTheEndStopsTheLoop() throws Exception {
        ManualClock clock = new ManualClock(true, 0);
        try (Replayer r = new Replayer(log, bus, clock)) {
            ReplayLoop loop = ReplayLoop.start(r);
            clock.awaitBlocked(1);
            r.pause();
            assertFalse(r.playing(), "paused");
            assertEquals(0, loop.restarts(), "a pause is no end of the log");
            assertTrue(r.position() < log.endNanos());
        }
    }
}
