package org.stagecraft.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/** The world model fed from the recorded single-robot session. */
class WorldModelTraceTest {
    static final String PLAYER = "127.0.0.1:6665";

    static Path trace(String name) {
        String dir = System.getProperty("stagecraft.traces");
        assertNotNull(dir, "-Dstagecraft.traces must name the trace corpus (tests/traces)");
        return Path.of(dir, name);
    }

    /** What a replay of the recorded session publishes: the spy's messages under the spy's keys. */
    static List<StreamMessage> recorded(String name) throws IOException {
        try (SessionLog log = SessionLogs.open(trace(name))) {
            return Replayer.allPublished(log);
        }
    }

    @Test
    void geometryRepliesMountTheSensorsAndPosesMoveTheRobot() throws Exception {
        List<StreamMessage> msgs = recorded("pioneer-laser-sonar.gt.trace.jsonl");
        WorldModel w = new WorldModel(10_000);
        RobotId robot = new RobotId(PLAYER);
        DeviceAddress sonar = new DeviceAddress(robot, 62, 0);
        assertFalse(w.mount(sonar).seen(), "defaults until a geometry is seen");

        StreamMessage lastPose = null;
        for (StreamMessage m : msgs) {
            w.accept(m);
            if (m.key().messageType() == 1 && m.key().deviceType() == 4 && m.key().subtype() == 1) {
                lastPose = m;
            }
        }
        // GET_GEOM replies, as libplayerc decoded them (see the decoded trace): position2d 0.44 x 0.38 at
        // x = -0.04; the sonar ring's 16 transducers, the first at (0.075, 0.13) facing 90 degrees.
        Mount body = w.mount(new DeviceAddress(robot, 4, 0));
        assertTrue(body.seen());
        assertEquals(0.44, body.length(), 1e-9);
        assertEquals(0.38, body.width(), 1e-9);
        assertEquals(-0.04, body.pose().x(), 1e-9);
        Mount ring = w.mount(sonar);
        assertEquals(16, ring.elements().size());
        assertEquals(0.075, ring.elements().get(0).x(), 1e-9);
        assertEquals(0.13, ring.elements().get(0).y(), 1e-9);
        assertEquals(Math.PI / 2, ring.elements().get(0).a(), 1e-9);
        assertEquals(1, w.mount(new DeviceAddress(robot, 62, 1)).elements().size());
        assertTrue(w.mount(new DeviceAddress(robot, 6, 0)).seen());

        Position2d.State s = (Position2d.State) Payloads.body(lastPose);
        RobotState r = w.robot(robot);
        assertTrue(r.poseSeen());
        assertEquals(s.pos().px(), r.pose().x(), 0);
        assertEquals(s.pos().pa(), r.pose().a(), 0);
        assertTrue(r.trail().size() > 10, "the robot drove: " + r.trail().size());
        assertEquals(List.of(r), w.robots());
    }

    @Test
    void feedsKeepOnlyTheNewestMessagePerStream() throws Exception {
        List<StreamMessage> msgs = recorded("pioneer-laser-sonar.gt.trace.jsonl");
        CountDownLatch changed = new CountDownLatch(1);
        LayerFeed feed = new LayerFeed(changed::countDown);
        StreamBus bus = new StreamBus(Runnable::run); // delivery on the publisher's thread: deterministic
        feed.subscribe(bus, StreamPattern.parse("type=1 dev=62 subtype=1"));
        StreamMessage lastSonar = null, lastLaserRanger = null;
        for (StreamMessage m : msgs) {
            bus.publish(m);
            StreamKey k = m.key();
            if (k.messageType() == 1 && k.deviceType() == 62 && k.subtype() == 1) {
                if (k.index() == 0) {
                    lastSonar = m;
                } else {
                    lastLaserRanger = m;
                }
            }
        }
        assertTrue(changed.await(5, TimeUnit.SECONDS));
        assertEquals(List.of(lastSonar, lastLaserRanger), feed.snapshot());
        feed.close();
        bus.close();
    }
}
