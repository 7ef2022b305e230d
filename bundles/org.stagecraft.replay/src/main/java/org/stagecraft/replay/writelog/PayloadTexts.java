package org.stagecraft.replay.writelog;

import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.msg.Blobfinder;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;

/**
 * The interfaces both Player's writelog and Stagecraft's codec know. Writelog also writes camera,
 * gps, imu, power and others, for which the codec has no message classes; it never writes simulation.
 */
final class PayloadTexts {
    private PayloadTexts() {
    }

    private static final Map<Integer, PayloadText> BY_INTERFACE = Map.of(
            Position2d.CODE, new PositionText(),
            Laser.CODE, new LaserText(),
            Sonar.CODE, new SonarText(),
            Ranger.CODE, new RangerText(),
            Bumper.CODE, new BumperText(),
            Fiducial.CODE, new FiducialText(),
            Blobfinder.CODE, new BlobfinderText());

    /** @return the payload text of an interface code, or null when there is none */
    static @Nullable PayloadText of(int interf) {
        return BY_INTERFACE.get(interf);
    }
}
