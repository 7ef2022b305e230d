package org.stagecraft.player.msg;

import org.stagecraft.player.codec.CodecContribution;
import org.stagecraft.player.codec.CodecRegistry;

/**
 * Player 3's interface names (libplayerinterface/interfaces/NNN_name.def) and the decoders for the
 * interfaces Stage and common robots use. Interfaces without a decoder here still have a name;
 * their payloads stay raw.
 */
public final class StandardInterfaces implements CodecContribution {

    private static final Object[][] NAMES = {
        {1, "player"}, {2, "power"}, {3, "gripper"}, {4, "position2d"}, {5, "sonar"}, {6, "laser"},
        {7, "blobfinder"}, {8, "ptz"}, {9, "audio"}, {10, "fiducial"}, {12, "speech"}, {13, "gps"},
        {14, "bumper"}, {20, "dio"}, {21, "aio"}, {22, "ir"}, {23, "wifi"}, {25, "localize"},
        {30, "position3d"}, {31, "simulation"}, {33, "blinkenlight"}, {40, "camera"}, {42, "map"},
        {44, "planner"}, {45, "log"}, {49, "joystick"}, {50, "speech_recognition"}, {51, "opaque"},
        {52, "position1d"}, {53, "actarray"}, {54, "limb"}, {55, "graphics2d"}, {56, "rfid"}, {57, "wsn"},
        {58, "graphics3d"}, {59, "health"}, {60, "imu"}, {61, "pointcloud3d"}, {62, "ranger"},
        {63, "vectormap"}, {64, "blackboard"}, {65, "stereo"}, {66, "coopobject"},
    };

    @Override
    public void contributeTo(CodecRegistry registry) {
        for (Object[] n : NAMES) {
            registry.registerInterface((Integer) n[0], (String) n[1]);
        }
        Universal.register(registry);
        PlayerDevice.register(registry);
        Position2d.register(registry);
        Sonar.register(registry);
        Laser.register(registry);
        Blobfinder.register(registry);
        Fiducial.register(registry);
        Bumper.register(registry);
        Simulation.register(registry);
        MapInterface.register(registry);
        Ranger.register(registry);
    }
}
