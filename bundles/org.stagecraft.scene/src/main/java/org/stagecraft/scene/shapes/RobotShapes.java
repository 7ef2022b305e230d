package org.stagecraft.scene.shapes;

import java.util.List;

import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RobotState;

/** A robot as the position2d layer draws it: footprint, heading, trail and velocity. */
public final class RobotShapes {
    /** The velocity arrow shows where the robot would be this many seconds from now. */
    public static final double VELOCITY_HORIZON_S = 1.0;

    private RobotShapes() {
    }

    /** Footprint rectangle (from the position2d geometry) centred on the body's mount pose, as triangles. */
    public static void footprint(RobotState r, FloatList triangles) {
        Pose2 body = r.pose().compose(r.body().pose());
        double hl = Math.max(0.05, r.body().length()) / 2, hw = Math.max(0.05, r.body().width()) / 2;
        SensorShapes.quad(body.toParentX(-hl, -hw), body.toParentY(-hl, -hw), body.toParentX(hl, -hw),
                body.toParentY(hl, -hw), body.toParentX(hl, hw), body.toParentY(hl, hw), body.toParentX(-hl, hw),
                body.toParentY(-hl, hw), triangles);
    }

    /** The heading: a triangle from the rear corners to the front centre (drawn in a contrasting shade). */
    public static void heading(RobotState r, FloatList triangles) {
        Pose2 body = r.pose().compose(r.body().pose());
        double hl = Math.max(0.05, r.body().length()) / 2, hw = Math.max(0.05, r.body().width()) / 2;
        triangles.add(body.toParentX(hl, 0), body.toParentY(hl, 0));
        triangles.add(body.toParentX(-hl * 0.2, hw * 0.6), body.toParentY(-hl * 0.2, hw * 0.6));
        triangles.add(body.toParentX(-hl * 0.2, -hw * 0.6), body.toParentY(-hl * 0.2, -hw * 0.6));
    }

    /** The trail as line segments, oldest first, ending at the current pose; points closer than {@code minStep} merged. */
    public static void trail(RobotState r, double minStep, FloatList lines) {
        List<Pose2> t = r.trail();
        Pose2 from = t.isEmpty() ? null : t.get(0);
        for (int i = 1; i < t.size(); i++) {
            Pose2 to = t.get(i);
            if (i < t.size() - 1 && Math.hypot(to.x() - from.x(), to.y() - from.y()) < minStep) {
                continue;
            }
            lines.add(from.x(), from.y());
            lines.add(to.x(), to.y());
            from = to;
        }
    }

    /** The velocity (robot frame vx, vy) as a segment from the robot to where it would be in 1 s. */
    public static void velocity(RobotState r, FloatList lines) {
        Pose2 p = r.pose();
        double vx = r.velocity().x(), vy = r.velocity().y();
        if (Math.hypot(vx, vy) < 1e-6) {
            return;
        }
        lines.add(p.x(), p.y());
        lines.add(p.toParentX(vx * VELOCITY_HORIZON_S, vy * VELOCITY_HORIZON_S),
                p.toParentY(vx * VELOCITY_HORIZON_S, vy * VELOCITY_HORIZON_S));
    }
}
