package org.stagecraft.spy.hold;

import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrWriter;

/** The message a hold injects: a position2d CMD_VEL of zero, addressed as the program's own commands. */
public final class ZeroVelocity {
    private ZeroVelocity() {
    }

    /**
     * @param last  the header of the program's last motion command to the device: host, robot,
     *              interface and index are copied so Player routes it exactly like the program's
     *              commands; so are timestamp and seq, which keeps them in the program's own time base
     *              (Player does not check either on commands)
     * @param state the motor state to send: the program's own from its last CMD_VEL, else 1 (motors on,
     *              so a driver brakes rather than lets the robot coast)
     */
    public static byte[] command(MessageHeader last, int state) {
        XdrWriter body = new XdrWriter(32);
        new Position2d.CmdVel(new Pose2d(0, 0, 0), state).encode(body);
        MessageHeader h = new MessageHeader(last.host(), last.robot(), Position2d.CODE, last.index(),
                MessageType.CMD.code(), MotionCommand.CMD_VEL, last.timestamp(), last.seq(), body.size());
        XdrWriter w = new XdrWriter(MessageHeader.SIZE + body.size());
        h.write(w);
        byte[] payload = body.toByteArray();
        w.raw(payload, 0, payload.length);
        return w.toByteArray();
    }
}
