package org.stagecraft.scene;

import java.util.List;

/**
 * Where a device sits on its robot, from the geometry replies seen on the wire: the device's pose in the
 * robot frame, its size (length along x, width along y) and, for rangers with several elements (a sonar
 * ring), the pose of each element in the device frame.
 *
 * @param seen false for the defaults used until a geometry reply has been seen
 */
public record Mount(Pose2 pose, double length, double width, List<Pose2> elements, boolean seen) {
    public Mount {
        elements = List.copyOf(elements);
    }

    /** Centred on the robot, pointing forward; the size of a Pioneer 2 body. */
    public static final Mount DEFAULT = new Mount(Pose2.ORIGIN, 0.44, 0.38, List.of(), false);
}
