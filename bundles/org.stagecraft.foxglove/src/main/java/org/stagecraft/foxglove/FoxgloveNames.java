package org.stagecraft.foxglove;

import org.stagecraft.player.msg.Blobfinder;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.MapInterface;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;

/**
 * Names of robots, frames and topics. A robot is the Player server its program talks to: Stage's
 * multi-robot worlds give each robot its own port, so the robot on {@code 127.0.0.1:6665} is
 * {@code robot6665}, its body frame is {@code robot6665}, its laser's frame {@code robot6665/laser0}
 * and its topics start with {@code /robot6665/}. Robots of other machines carry the host too
 * ({@code robot10.0.0.7_6665}), so robots behind several spies coexist in one view.
 */
public final class FoxgloveNames {
    /** The fixed frame every robot's pose is in. */
    public static final String WORLD = "world";
    /** Stagecraft's own topics: diagnostics and session events. */
    public static final String DIAGNOSTICS_TOPIC = "/stagecraft/diagnostics";
    public static final String EVENTS_TOPIC = "/stagecraft/events";

    private FoxgloveNames() {
    }

    /** The robot of a Player address such as {@code 127.0.0.1:6665}. */
    public static String robot(String playerAddress) {
        int colon = playerAddress.lastIndexOf(':');
        String host = colon < 0 ? "" : playerAddress.substring(0, colon);
        String port = colon < 0 ? playerAddress : playerAddress.substring(colon + 1);
        boolean local = host.isEmpty() || host.equals("localhost") || host.startsWith("127.") || host.equals("0.0.0.0")
                || host.equals("::1") || host.equals("[::1]");
        return local ? "robot" + port : "robot" + host.replaceAll("[^A-Za-z0-9.\\-]", "") + "_" + port;
    }

    /** A device of a robot, e.g. {@code laser0}: the interface's Player name and the index. */
    public static String device(int interf, int index) {
        return interfaceName(interf) + index;
    }

    /** The frame of a robot's device: {@code robot6665/laser0}. Position2d:0 is the robot itself. */
    public static String deviceFrame(String robot, int interf, int index) {
        return interf == Position2d.CODE && index == 0 ? robot : robot + "/" + device(interf, index);
    }

    /** A topic of a robot's device: {@code /robot6665/laser0/scan}. */
    public static String deviceTopic(String robot, int interf, int index, String what) {
        return "/" + robot + "/" + device(interf, index) + "/" + what;
    }

    /** A topic of the robot as a whole: {@code /robot6665/pose}. */
    public static String robotTopic(String robot, String what) {
        return "/" + robot + "/" + what;
    }

    static String interfaceName(int interf) {
        return switch (interf) {
            case Position2d.CODE -> "position2d";
            case Laser.CODE -> "laser";
            case Ranger.CODE -> "ranger";
            case Sonar.CODE -> "sonar";
            case Bumper.CODE -> "bumper";
            case Fiducial.CODE -> "fiducial";
            case Blobfinder.CODE -> "blobfinder";
            case MapInterface.CODE -> "map";
            default -> "interface" + interf;
        };
    }
}
