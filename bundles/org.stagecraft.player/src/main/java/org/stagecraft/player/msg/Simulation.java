package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.CMD;
import static org.stagecraft.player.wire.MessageType.REQ;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 31, "simulation": the simulator itself (031_simulation.def). */
public final class Simulation {
    public static final int CODE = 31;

    private Simulation() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "simulation");
        r.register(CODE, REQ, 1, "GET_POSE2D", PoseReq2d::read);
        r.register(CODE, REQ, 2, "SET_POSE2D", PoseReq2d::read);
        r.register(CODE, REQ, 3, "GET_POSE3D", PoseReq3d::read);
        r.register(CODE, REQ, 4, "SET_POSE3D", PoseReq3d::read);
        r.register(CODE, REQ, 5, "GET_PROPERTY", PropertyReq::read);
        r.register(CODE, REQ, 6, "SET_PROPERTY", PropertyReq::read);
        r.registerEmpty(CODE, CMD, 1, "PAUSE");
        r.registerEmpty(CODE, CMD, 2, "RESET");
        r.registerEmpty(CODE, CMD, 3, "SAVE");
    }

    /** player_simulation_pose2d_req: a named object's pose. */
    public record PoseReq2d(int nameCount, ByteArray name, Pose2d pose) implements MessageBody {
        static PoseReq2d read(XdrReader r) {
            return new PoseReq2d(r.uint32(), Xdr.bytes(r), Pose2d.read(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(nameCount);
            Xdr.bytes(w, name);
            pose.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "name_count", nameCount);
            Xdr.text(v, "name", name);
            Xdr.struct(v, "pose", pose);
        }
    }

    /** player_simulation_pose3d_req. */
    public record PoseReq3d(int nameCount, ByteArray name, Pose3d pose, double simtime) implements MessageBody {
        static PoseReq3d read(XdrReader r) {
            return new PoseReq3d(r.uint32(), Xdr.bytes(r), Pose3d.read(r), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(nameCount);
            Xdr.bytes(w, name);
            pose.encode(w);
            w.float64(simtime);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "name_count", nameCount);
            Xdr.text(v, "name", name);
            Xdr.struct(v, "pose", pose);
            v.float64("simtime", simtime);
        }
    }

    /**
     * player_simulation_property_req. The value is raw memory of the simulator's host (Player does
     * no conversion), so it is kept as opaque bytes.
     */
    public record PropertyReq(int nameCount, ByteArray name, int propCount, ByteArray prop, int index, int valueCount,
            ByteArray value) implements MessageBody {
        static PropertyReq read(XdrReader r) {
            return new PropertyReq(r.uint32(), Xdr.bytes(r), r.uint32(), Xdr.bytes(r), r.uint32(), r.uint32(),
                    Xdr.bytes(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(nameCount);
            Xdr.bytes(w, name);
            w.uint32(propCount);
            Xdr.bytes(w, prop);
            w.uint32(index).uint32(valueCount);
            Xdr.bytes(w, value);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "name_count", nameCount);
            Xdr.text(v, "name", name);
            Xdr.u32(v, "prop_count", propCount);
            Xdr.text(v, "prop", prop);
            Xdr.u32(v, "index", index);
            Xdr.u32(v, "value_count", valueCount);
            v.opaque("value", value.toArray());
        }
    }
}
