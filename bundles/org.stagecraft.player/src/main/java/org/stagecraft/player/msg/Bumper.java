package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.DATA;
import static org.stagecraft.player.wire.MessageType.REQ;

import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 14, "bumper" (014_bumper.def). */
public final class Bumper {
    public static final int CODE = 14;
    /** Subtype DATA 2: the bumpers' geometry, pushed. */
    public static final int DATA_GEOM = 2;
    /** Subtype REQ 1: asks for the geometry. */
    public static final int REQ_GET_GEOM = 1;

    private Bumper() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "bumper");
        r.register(CODE, DATA, 1, "STATE", State::read);
        r.register(CODE, DATA, DATA_GEOM, "GEOM", Geom::read);
        r.register(CODE, REQ, REQ_GET_GEOM, "GET_GEOM", Geom::read);
    }

    /** player_bumper_data: one byte per bumper, non-zero when pressed. */
    public record State(int bumpersCount, ByteArray bumpers) implements MessageBody {
        static State read(XdrReader r) {
            return new State(r.uint32(), Xdr.bytes(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(bumpersCount);
            Xdr.bytes(w, bumpers);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "bumpers_count", bumpersCount);
            Xdr.uint8s(v, "bumpers", bumpers);
        }
    }

    /** player_bumper_define: one bumper's pose, length and radius of curvature. */
    public record Define(Pose3d pose, float length, float radius) implements MessageBody {
        static final int XDR_SIZE = Pose3d.XDR_SIZE + 8;

        static Define read(XdrReader r) {
            return new Define(Pose3d.read(r), r.float32(), r.float32());
        }

        @Override
        public void encode(XdrWriter w) {
            pose.encode(w);
            w.float32(length).float32(radius);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "pose", pose);
            v.float32("length", length);
            v.float32("radius", radius);
        }
    }

    /** player_bumper_geom. */
    public record Geom(int bumperDefCount, List<Define> bumperDef) implements MessageBody {
        static Geom read(XdrReader r) {
            return new Geom(r.uint32(), Xdr.structs(r, Define.XDR_SIZE, Define::read));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(bumperDefCount);
            Xdr.structs(w, bumperDef);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "bumper_def_count", bumperDefCount);
            Xdr.structs(v, "bumper_def", bumperDef);
        }
    }
}
