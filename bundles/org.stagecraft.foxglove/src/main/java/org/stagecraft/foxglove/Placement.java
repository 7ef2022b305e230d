package org.stagecraft.foxglove;

import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.msg.Geometry.Pose3d;

/**
 * Where a device sits on its robot, from the geometry Player sent: its pose in the robot's frame
 * (planar, at a height), its size and, for a ring of rangers (a sonar), each element's pose in the
 * device's frame.
 *
 * @param seen false for the default (at the robot's origin, facing forward) used until a geometry
 *             reply is seen
 */
record Placement(double x, double y, double z, double yaw, double length, double width, double height,
        List<double[]> elements, boolean seen) {

    static final Placement DEFAULT = new Placement(0, 0, 0, 0, 0, 0, 0, List.of(), false);

    static Placement of(Pose3d p, double length, double width, double height, List<Pose3d> elements) {
        List<double[]> e = new ArrayList<>(elements.size());
        for (Pose3d q : elements) {
            e.add(new double[] { sane(q.px()), sane(q.py()), sane(q.pyaw()) });
        }
        return new Placement(sane(p.px()), sane(p.py()), sane(p.pz()), sane(p.pyaw()), size(length), size(width),
                size(height), List.copyOf(e), true);
    }

    // Stage leaves some geometry doubles uninitialised (denormals like 4.6e-310, or garbage): never
    // let a NaN, an infinity or an absurd value into a transform or a size.
    static double sane(double v) {
        return Double.isFinite(v) && Math.abs(v) < 1e6 ? v : 0;
    }

    private static double size(double v) {
        return Math.abs(sane(v));
    }
}
