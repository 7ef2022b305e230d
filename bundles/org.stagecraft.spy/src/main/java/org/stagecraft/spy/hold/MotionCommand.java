package org.stagecraft.spy.hold;

import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.xdr.XdrReader;

/**
 * Which Player messages move a robot, and whether one asks it to move. Every position2d command
 * (CMD_VEL, CMD_POS, CMD_CAR, CMD_VEL_HEAD, and any subtype the codec does not know yet) is a motion
 * command: while a hold is on none of them may reach Player.
 */
public final class MotionCommand {
    public static final int CMD_VEL = 1;
    public static final int CMD_POS = 2;
    public static final int CMD_CAR = 3;
    public static final int CMD_VEL_HEAD = 4;

    /** The device a command is addressed to, exactly as the program addressed it. */
    public record Device(int host, int robot, int interf, int index) {
        static Device of(MessageHeader h) {
            return new Device(h.host(), h.robot(), h.interf(), h.index());
        }

        @Override
        public String toString() {
            return "position2d:" + index;
        }
    }

    private MotionCommand() {
    }

    public static boolean isMotion(MessageHeader h) {
        return isMotion(h.interf(), h.type());
    }

    static boolean isMotion(int interf, int type) {
        return interf == Position2d.CODE && type == MessageType.CMD.code();
    }

    /**
     * Whether the command asks the robot to move; a payload too short for its layout counts as moving
     * (the watchdog errs on the side of stopping).
     */
    public static boolean moving(MessageHeader h, byte[] payload) {
        try {
            XdrReader r = new XdrReader(payload, 0, payload.length);
            return switch (h.subtype()) {
                case CMD_VEL -> r.float64() != 0 || r.float64() != 0 || r.float64() != 0;
                case CMD_CAR, CMD_VEL_HEAD -> r.float64() != 0; // velocity; the angle alone does not move it
                default -> true; // CMD_POS: a goal to drive to
            };
        } catch (RuntimeException e) {
            return true;
        }
    }

    /** The motor state of a CMD_VEL payload (the word after the three doubles), or -1. */
    static int velState(MessageHeader h, byte[] payload) {
        if (h.subtype() != CMD_VEL || payload.length < 28) {
            return -1;
        }
        return payload[27] & 0xff;
    }
}
