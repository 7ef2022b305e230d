package org.stagecraft.player.it;

import java.io.IOException;
import java.time.Duration;

import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.Geometry;
import org.stagecraft.player.msg.Simulation;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.tools.world.DeviceRequests;

/**
 * A test's own Player client of Stage's simulation device (simulation:0 on Player's port): where a model is, and
 * the simulated time of Stage's answer (the reply's header timestamp). Connected to Player directly, not through
 * the spy: it observes the world, it is not a robot program.
 */
final class StageSimulation implements AutoCloseable {
    private static final int GET_POSE2D = 1;

    /** A model's pose and the simulated time Stage answered at. */
    record Pose(double x, double y, double a, double simTime) {
        double distanceTo(Pose o) {
            return Math.hypot(x - o.x, y - o.y);
        }
    }

    private final DeviceRequests device;

    StageSimulation(int port) throws IOException {
        device = DeviceRequests.open("127.0.0.1", port, Simulation.CODE, 0, Duration.ofSeconds(10));
    }

    Pose pose(String model) throws IOException {
        ByteArray name = ByteArray.ofText(model);
        DeviceRequests.Answer a = device.request(GET_POSE2D, new Simulation.PoseReq2d(name.size(), name, new Geometry.Pose2d(0, 0, 0)));
        XdrReader r = new XdrReader(a.payload());
        r.uint32();
        r.bytes();
        Geometry.Pose2d p = Geometry.Pose2d.read(r);
        return new Pose(p.px(), p.py(), p.pa(), a.timestamp());
    }

    @Override
    public void close() {
        device.close();
    }
}
