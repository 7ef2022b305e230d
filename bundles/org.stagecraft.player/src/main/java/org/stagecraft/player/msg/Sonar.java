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

/** Interface 5, "sonar": arrays of ultrasonic rangers (005_sonar.def). */
public final class Sonar {
    public static final int CODE = 5;
    /** Subtype DATA 2: the transducers' poses, pushed. */
    public static final int DATA_GEOM = 2;
    /** Subtype REQ 1: asks for the transducers' poses. */
    public static final int REQ_GET_GEOM = 1;

    private Sonar() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "sonar");
        r.register(CODE, DATA, 1, "RANGES", Ranges::read);
        r.register(CODE, DATA, DATA_GEOM, "GEOM", Geom::read);
        r.register(CODE, REQ, REQ_GET_GEOM, "GET_GEOM", Geom::read);
        r.register(CODE, REQ, 2, "POWER", Scalar.Uint8.decoder("state"));
    }

    /** player_sonar_data. */
    public record Ranges(int rangesCount, FloatArray ranges) implements MessageBody {
        static Ranges read(XdrReader r) {
            return new Ranges(r.uint32(), Xdr.floats(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(rangesCount);
            Xdr.floats(w, ranges);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "ranges_count", rangesCount);
            Xdr.floats(v, "ranges", ranges);
        }
    }

    /** player_sonar_geom: the pose of each transducer in robot coordinates. */
    public record Geom(int posesCount, List<Pose3d> poses) implements MessageBody {
        static Geom read(XdrReader r) {
            return new Geom(r.uint32(), Xdr.structs(r, Pose3d.XDR_SIZE, Pose3d::read));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(posesCount);
            Xdr.structs(w, poses);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "poses_count", posesCount);
            Xdr.structs(v, "poses", poses);
        }
    }
}
