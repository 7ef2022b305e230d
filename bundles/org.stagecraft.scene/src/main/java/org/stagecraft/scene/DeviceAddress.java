package org.stagecraft.scene;

import org.stagecraft.streams.StreamKey;

/** One device of one robot: interface code and index, e.g. ranger:1 of the robot on port 6665. */
public record DeviceAddress(RobotId robot, int interf, int index) {
    public static DeviceAddress of(StreamKey key) {
        return new DeviceAddress(RobotId.of(key), key.deviceType(), key.index());
    }
}
