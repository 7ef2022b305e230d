package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.ui.internal.ReplayAtStartup;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.RobotId;
import org.stagecraft.scene.RobotState;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.scene.WorldModel;
import org.stagecraft.streams.StreamBus;

/**
 * STAGECRAFT_REPLAY at workbench start, on a bus of its own: the recorded robot appears in the bus's
 * shared world (its geometry reply mounts its base and sonar ring, its pose places it), played by the
 * Replayer under the spy's keys.
 */
class ReplayAtStartupTest {

    @Test
    void theRecordedRobotAppearsInTheBusWorldWithItsGeometryAndPose() throws Exception {
        RobotId robot = new RobotId(TestLogs.PORT_LISTEN);
        try (StreamBus bus = new StreamBus()) {
            WorldModel world = SharedWorld.of(bus).world();
            CountDownLatch seen = new CountDownLatch(1);
            SharedWorld.of(bus).listen(() -> {
                RobotState r = world.robot(robot);
                if (r.poseSeen() && r.body().seen() && world.mount(new DeviceAddress(robot, 62, 0)).seen()) {
                    seen.countDown();
                }
            });
            try (ReplayAtStartup.Running running = ReplayAtStartup.start(TraceCorpus.file(TestLogs.TRACE), bus)) {
                assertTrue(seen.await(60, TimeUnit.SECONDS), "the robot was mounted and placed: " + world.robots());
                assertTrue(running.replayer().playing());
                assertEquals(0.44, world.robot(robot).body().length(), 1e-9, "the recorded GET_GEOM reply");
            }
        }
    }
}
