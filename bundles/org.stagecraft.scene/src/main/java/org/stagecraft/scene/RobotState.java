package org.stagecraft.scene;

import java.util.List;

/**
 * A robot as last seen: pose and velocity from position2d, the trail of recent poses (oldest first) and
 * the footprint from the position2d geometry.
 *
 * @param poseSeen false until the first position2d state arrived (the robot is then drawn at the origin)
 */
public record RobotState(RobotId id, Pose2 pose, Pose2 velocity, boolean stall, List<Pose2> trail, Mount body,
        boolean poseSeen) {
}
