package org.stagecraft.scene;

import org.stagecraft.streams.StreamKey;

/**
 * A robot as the Robot View tells robots apart: by the address of the Player server it talks to
 * ("127.0.0.1:6665"). Stage's multi-robot worlds give each robot its own port, so the port is the robot.
 */
public record RobotId(String address) implements Comparable<RobotId> {

    /** The Player side of a stream: the source of what the server sends, the destination of the rest. */
    public static RobotId of(StreamKey key) {
        return new RobotId(fromServer(key.messageType()) ? key.source() : key.destination());
    }

    /** DATA, RESP_ACK, SYNCH and RESP_NACK come from the server; CMD and REQ go to it. */
    static boolean fromServer(int messageType) {
        return messageType != 2 && messageType != 3;
    }

    @Override
    public int compareTo(RobotId o) {
        return address.compareTo(o.address);
    }

    @Override
    public String toString() {
        return address;
    }
}
