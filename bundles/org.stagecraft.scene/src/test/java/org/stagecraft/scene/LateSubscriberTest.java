package org.stagecraft.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.stagecraft.spy.hold.HoldAction;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.WorldChange;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.HoldStreams;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/**
 * A view opened while the robot program is suspended (nothing new arrives) shows the last known state:
 * the layers start from the newest message of each stream, and the hold overlay from the last hold state.
 * The bus delivers on the publishing thread here, so every assertion follows its publish directly.
 */
class LateSubscriberTest {
    private static final StreamKey LASER = new StreamKey("127.0.0.1:6665", "127.0.0.1:40000", 1, 6, 0, 1);
    private static final StreamKey SONAR = new StreamKey("127.0.0.1:6665", "127.0.0.1:40000", 1, 5, 0, 1);

    private static StreamMessage m(StreamKey k, long t) {
        return new StreamMessage(k, t, "payload " + t);
    }

    @Test
    void aLayerSubscribedLateStartsFromTheNewestMessageOfEachMatchingStream() {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            LastMessages.of(bus); // the workbench makes it at start (SharedWorld)
            bus.publish(m(LASER, 1));
            bus.publish(m(LASER, 2));
            bus.publish(m(SONAR, 3));

            AtomicInteger changes = new AtomicInteger();
            LayerFeed late = new LayerFeed(changes::incrementAndGet).subscribe(bus, StreamPattern.any().deviceType(6));
            assertEquals(List.of(m(LASER, 2)), late.snapshot(), "the newest laser scan, and only the laser");
            assertEquals(1, changes.get(), "a redraw was asked for");
            assertTrue(late.version() > 0);

            bus.publish(m(LASER, 4));
            assertEquals(List.of(m(LASER, 4)), late.snapshot(), "newer data replaces the seed");
            late.close();
        }
    }

    @Test
    void withoutAStoreALateLayerStartsEmptyAsBefore() {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            bus.publish(m(LASER, 1));
            LayerFeed late = new LayerFeed(() -> {
            }).subscribe(bus, StreamPattern.any());
            assertEquals(List.of(), late.snapshot());
            assertEquals(0, late.version());
        }
    }

    @Test
    void theSharedWorldKeepsTheLastMessagesAndTheStoreIsBounded() {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            SharedWorld.of(bus);
            for (int port = 0; port < LastMessages.MAX_STREAMS + 10; port++) {
                bus.publish(m(new StreamKey("127.0.0.1:6665", "127.0.0.1:" + (20000 + port), 1, 6, 0, 1), port));
            }
            LastMessages store = LastMessages.find(bus).orElseThrow();
            assertEquals(LastMessages.MAX_STREAMS, store.streams(), "the least recently used streams were forgotten");
            assertEquals(1, store.matching(StreamPattern.any().destination("127.0.0.1:" + (20000 + LastMessages.MAX_STREAMS + 9)))
                    .size(), "the newest is kept");
            assertEquals(0, store.matching(StreamPattern.any().destination("127.0.0.1:20000")).size(), "the oldest went");
        }
    }

    @Test
    void theHoldOverlayShowsTheLastHoldStateToAViewOpenedLate() {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            LastMessages.of(bus);
            HoldState held = new HoldState(true, true, Map.of(HoldReason.SUSPENDED, 1), 0, 1);
            bus.publish(new StreamMessage(HoldStreams.STATE, 1, held));

            AtomicInteger changes = new AtomicInteger();
            try (HoldStatus status = new HoldStatus(bus, changes::incrementAndGet)) {
                assertEquals(held, status.state());
                assertEquals("HELD (suspended in the debugger)", status.overlayText());

                bus.publish(new StreamMessage(HoldStreams.STATE, 2,
                        new HoldState(true, true, Map.of(HoldReason.SUSPENDED, 1, HoldReason.EMERGENCY_STOP, 1), 0, 1)));
                assertEquals("HELD (suspended in the debugger, emergency stop)", status.overlayText());
                bus.publish(new StreamMessage(HoldStreams.STATE, 3, new HoldState(true, false, Map.of(), 0, 1)));
                assertNull(status.overlayText(), "released: nothing drawn");
                assertEquals(2, changes.get());
            }
        }
    }

    @Test
    void theHoldOverlaySaysTheWorldIsFrozenAndWhichReadingStoppedTheProgram() {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            LastMessages.of(bus);
            bus.publish(new StreamMessage(HoldStreams.STATE, 1,
                    new HoldState(true, true, Map.of(HoldReason.DATA_BREAKPOINT, 1), 0, 1)));
            org.stagecraft.spy.proxy.ConnectionInfo c = new org.stagecraft.spy.proxy.ConnectionInfo(1, 6665, "127.0.0.1:40000",
                    "127.0.0.1:6665", "127.0.0.1:7665");
            org.stagecraft.player.wire.MessageHeader h = new org.stagecraft.player.wire.MessageHeader(0, 6665, 6, 0, 1, 1, 12.3, 7, 0);
            org.stagecraft.player.msg.Laser.Scan scan = new org.stagecraft.player.msg.Laser.Scan(-1.5f, 1.5f, 1.5f, 8f, 3,
                    org.stagecraft.player.msg.FloatArray.of(2f, 0.78f, 3f), 0, org.stagecraft.player.msg.ByteArray.EMPTY, 0);
            HoldAction hit = new HoldAction(c, org.stagecraft.spy.log.HoldEntry.Action.BREAK, 480, 480, h,
                    org.stagecraft.player.codec.PlayerEncoder.encode(h, scan),
                    "robot data breakpoint: laser:0 min(ranges) < 0.8 (laser:0 min(ranges) = 0.78 m)", List.of("ranges[1]"));
            bus.publish(new StreamMessage(HoldStreams.actionKey(hit), 2, hit));
            bus.publish(new StreamMessage(HoldStreams.WORLD, 3, new WorldChange(true, 12_300_000, "world frozen")));

            // a view opened now (late) says all three at once
            try (HoldStatus status = new HoldStatus(bus, () -> { })) {
                assertEquals("HELD (robot data breakpoint); world frozen; laser:0 min(ranges) < 0.8 (laser:0 min(ranges) = 0.78 m)",
                        status.overlayText());
                BreakReading reading = status.breakReading();
                assertEquals(new BreakReading(new DeviceAddress(new RobotId("127.0.0.1:6665"), 6, 0), scan, List.of("ranges[1]")),
                        reading, "the reading to mark: the laser's message, decoded, and its deciding beam");
                bus.publish(new StreamMessage(HoldStreams.WORLD, 4, new WorldChange(false, 12_300_000, "world runs on")));
                bus.publish(new StreamMessage(HoldStreams.STATE, 5, new HoldState(true, true, Map.of(HoldReason.SUSPENDED, 1), 0, 1)));
                assertEquals("HELD (suspended in the debugger)", status.overlayText(),
                        "the breakpoint's reading is said only while it holds; the world runs again");
                assertNull(status.breakReading(), "and marked only while it holds");
            }
        }
    }
}
