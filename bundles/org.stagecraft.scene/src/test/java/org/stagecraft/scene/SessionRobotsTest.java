package org.stagecraft.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/**
 * Issue 24, item 5: one session's robots do not clutter the next one's Robot View. A robot whose program
 * disconnected stays as last seen (to look at after the run); when the next session's robot appears, the
 * ended robots are forgotten with their trails, mounts and last data.
 */
class SessionRobotsTest {
    private static final String FIRST = "127.0.0.1:7001", SECOND = "127.0.0.1:7101";
    private static final String FIRST_CLIENT = "127.0.0.1:40001", SECOND_CLIENT = "127.0.0.1:40002";

    private static StreamKey pose(String player, String client) {
        return new StreamKey(player, client, 1, Position2d.CODE, 0, Position2d.DATA_STATE);
    }

    private static StreamKey laser(String player, String client) {
        return new StreamKey(player, client, 1, 6, 0, 1);
    }

    private static StreamMessage at(StreamKey k, double x, double y) {
        return new StreamMessage(k, 1, new Position2d.State(new Pose2d(x, y, 0), new Pose2d(0, 0, 0), 0));
    }

    @Test
    void anEndedRobotStaysUntilTheNextSessionsRobotComes() {
        WorldModel w = new WorldModel();
        RobotId first = new RobotId(FIRST), second = new RobotId(SECOND);
        w.accept(at(pose(FIRST, FIRST_CLIENT), -7, -7));
        w.accept(at(pose(FIRST, FIRST_CLIENT), -6, -7));
        w.released(Set.of(pose(FIRST, FIRST_CLIENT), laser(FIRST, FIRST_CLIENT)));
        assertTrue(w.ended(first));
        assertEquals(List.of(first), w.robots().stream().map(RobotState::id).toList(), "still drawn as last seen");
        assertEquals(2, w.robot(first).trail().size());

        w.accept(at(pose(SECOND, SECOND_CLIENT), 1, 1));
        assertEquals(List.of(second), w.robots().stream().map(RobotState::id).toList(), "the earlier session's robot is gone");
        assertTrue(w.forgotten(first));
        assertFalse(w.ended(first));
        assertEquals(1, w.forgetting());
    }

    /** The bus tells the release and delivers the last poses on different threads: either may come first. */
    @Test
    void aReleaseThatOvertakesTheLastPoseStillEndsTheRobot() {
        WorldModel w = new WorldModel();
        RobotId first = new RobotId(FIRST);
        w.released(Set.of(pose(FIRST, FIRST_CLIENT)));
        w.accept(at(pose(FIRST, FIRST_CLIENT), -7, -7)); // its last pose, delivered late
        assertTrue(w.ended(first));
        w.accept(at(pose(SECOND, SECOND_CLIENT), 1, 1));
        assertTrue(w.forgotten(first));
    }

    @Test
    void aRobotThatMovesAgainHasNotEnded() {
        WorldModel w = new WorldModel();
        RobotId first = new RobotId(FIRST);
        w.accept(at(pose(FIRST, FIRST_CLIENT), 0, 0));
        w.released(Set.of(pose(FIRST, FIRST_CLIENT))); // one of its programs went; another drives it on
        w.accept(at(pose(FIRST, "127.0.0.1:40009"), 0.5, 0));
        assertFalse(w.ended(first));
        w.accept(at(pose(SECOND, SECOND_CLIENT), 1, 1));
        assertEquals(2, w.robots().size(), "two robots of one session");
        assertEquals(0, w.forgetting());
    }

    @Test
    void theBusesWorldAndLastDataForgetTheEarlierSessionWhenTheNextOneComes() {
        try (StreamBus bus = new StreamBus(Runnable::run)) {
            SharedWorld shared = SharedWorld.of(bus);
            LastMessages last = LastMessages.of(bus);
            LayerFeed layer = new LayerFeed(() -> { }).subscribe(bus, StreamPattern.any().deviceType(6));
            bus.publish(at(pose(FIRST, FIRST_CLIENT), -7, -7));
            bus.publish(new StreamMessage(laser(FIRST, FIRST_CLIENT), 2, "first session's scan"));
            bus.release(FIRST_CLIENT); // the first session's program ended
            assertTrue(shared.world().ended(new RobotId(FIRST)));
            assertEquals(1, last.matching(StreamPattern.any().deviceType(6)).size(), "its last scan is kept to look at");

            bus.publish(at(pose(SECOND, SECOND_CLIENT), 1, 1)); // the next session
            assertTrue(shared.world().forgotten(new RobotId(FIRST)));
            assertEquals(List.of(), last.matching(StreamPattern.any().deviceType(6)), "a view opened now starts without it");
            assertTrue(layer.forget(k -> shared.world().forgotten(RobotId.of(k))), "a view's layer drops it when it draws");
            assertEquals(List.of(), layer.snapshot());
            layer.close();
        }
    }
}
