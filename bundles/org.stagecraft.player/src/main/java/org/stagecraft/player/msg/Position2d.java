package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.CMD;
import static org.stagecraft.player.wire.MessageType.DATA;
import static org.stagecraft.player.wire.MessageType.REQ;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 4, "position2d": planar mobile bases (004_position2d.def). */
public final class Position2d {
    public static final int CODE = 4;
    /** Subtype DATA 1: the robot's odometric pose, velocity and stall. */
    public static final int DATA_STATE = 1;
    /** Subtype DATA 2: the base's geometry, pushed. */
    public static final int DATA_GEOM = 2;
    /** Subtype REQ 1: asks for the geometry; the reply carries it. */
    public static final int REQ_GET_GEOM = 1;

    private Position2d() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "position2d");
        r.register(CODE, DATA, DATA_STATE, "STATE", State::read);
        r.register(CODE, DATA, DATA_GEOM, "GEOM", DeviceGeom::read);
        r.register(CODE, CMD, 1, "VEL", CmdVel::read);
        r.register(CODE, CMD, 2, "POS", CmdPos::read);
        r.register(CODE, CMD, 3, "CAR", CmdCar::read);
        r.register(CODE, CMD, 4, "VEL_HEAD", CmdCar::read);
        r.register(CODE, REQ, REQ_GET_GEOM, "GET_GEOM", DeviceGeom::read);
        r.register(CODE, REQ, 2, "MOTOR_POWER", Scalar.Uint8.decoder("state"));
        r.register(CODE, REQ, 3, "VELOCITY_MODE", Scalar.Uint32.decoder("value"));
        r.register(CODE, REQ, 4, "POSITION_MODE", Scalar.Uint32.decoder("state"));
        r.register(CODE, REQ, 5, "SET_ODOM", in -> new SetOdom(Pose2d.read(in)));
        r.registerEmpty(CODE, REQ, 6, "RESET_ODOM");
        r.register(CODE, REQ, 7, "SPEED_PID", Pid::read);
        r.register(CODE, REQ, 8, "POSITION_PID", Pid::read);
        r.register(CODE, REQ, 9, "SPEED_PROF", SpeedProf::read);
    }

    /** player_position2d_data: odometric pose, velocity and stall flag. */
    public record State(Pose2d pos, Pose2d vel, int stall) implements MessageBody {
        static State read(XdrReader r) {
            return new State(Pose2d.read(r), Pose2d.read(r), r.uint8());
        }

        @Override
        public void encode(XdrWriter w) {
            pos.encode(w);
            vel.encode(w);
            w.uint8(stall);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "pos", pos);
            Xdr.struct(v, "vel", vel);
            v.integer("stall", stall);
        }
    }

    /** player_position2d_cmd_vel. */
    public record CmdVel(Pose2d vel, int state) implements MessageBody {
        static CmdVel read(XdrReader r) {
            return new CmdVel(Pose2d.read(r), r.uint8());
        }

        @Override
        public void encode(XdrWriter w) {
            vel.encode(w);
            w.uint8(state);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "vel", vel);
            v.integer("state", state);
        }
    }

    /** player_position2d_cmd_pos. */
    public record CmdPos(Pose2d pos, Pose2d vel, int state) implements MessageBody {
        static CmdPos read(XdrReader r) {
            return new CmdPos(Pose2d.read(r), Pose2d.read(r), r.uint8());
        }

        @Override
        public void encode(XdrWriter w) {
            pos.encode(w);
            vel.encode(w);
            w.uint8(state);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "pos", pos);
            Xdr.struct(v, "vel", vel);
            v.integer("state", state);
        }
    }

    /** player_position2d_cmd_car and player_position2d_cmd_vel_head (same layout). */
    public record CmdCar(double velocity, double angle) implements MessageBody {
        static CmdCar read(XdrReader r) {
            return new CmdCar(r.float64(), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float64(velocity).float64(angle);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("velocity", velocity);
            v.float64("angle", angle);
        }
    }

    /** player_position2d_set_odom_req. */
    public record SetOdom(Pose2d pose) implements MessageBody {
        @Override
        public void encode(XdrWriter w) {
            pose.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "pose", pose);
        }
    }

    /** player_position2d_speed_pid_req / position_pid_req. */
    public record Pid(float kp, float ki, float kd) implements MessageBody {
        static Pid read(XdrReader r) {
            return new Pid(r.float32(), r.float32(), r.float32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(kp).float32(ki).float32(kd);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("kp", kp);
            v.float32("ki", ki);
            v.float32("kd", kd);
        }
    }

    /** player_position2d_speed_prof_req. */
    public record SpeedProf(float speed, float acc) implements MessageBody {
        static SpeedProf read(XdrReader r) {
            return new SpeedProf(r.float32(), r.float32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(speed).float32(acc);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("speed", speed);
            v.float32("acc", acc);
        }
    }
}
