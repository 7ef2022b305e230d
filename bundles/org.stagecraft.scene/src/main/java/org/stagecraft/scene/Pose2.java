package org.stagecraft.scene;

import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Geometry.Pose3d;

/**
 * A planar pose: position [m] and heading [rad, counter-clockwise from +x]. Composition follows the
 * robotics convention: {@code robot.compose(mount)} is the mount's pose in the robot's parent frame.
 */
public record Pose2(double x, double y, double a) {
    public static final Pose2 ORIGIN = new Pose2(0, 0, 0);

    public static Pose2 of(Pose2d p) {
        return new Pose2(p.px(), p.py(), p.pa());
    }

    /** The planar part of a 3D pose (Player's geometry replies): x, y and yaw. */
    public static Pose2 of(Pose3d p) {
        return new Pose2(finite(p.px()), finite(p.py()), finite(p.pyaw()));
    }

    /** This pose followed by {@code local}, which is expressed in this pose's frame. */
    public Pose2 compose(Pose2 local) {
        double c = Math.cos(a), s = Math.sin(a);
        return new Pose2(x + c * local.x - s * local.y, y + s * local.x + c * local.y, a + local.a);
    }

    /** x of the point (lx, ly) of this frame, in the parent frame. */
    public double toParentX(double lx, double ly) {
        return x + Math.cos(a) * lx - Math.sin(a) * ly;
    }

    /** y of the point (lx, ly) of this frame, in the parent frame. */
    public double toParentY(double lx, double ly) {
        return y + Math.sin(a) * lx + Math.cos(a) * ly;
    }

    // Stage leaves some geometry doubles uninitialised (denormals like 4.6e-310, or worse): never let
    // a NaN or infinity into a transform.
    private static double finite(double v) {
        return Double.isFinite(v) ? v : 0;
    }
}
