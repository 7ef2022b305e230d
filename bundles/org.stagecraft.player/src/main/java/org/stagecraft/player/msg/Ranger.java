package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.DATA;
import static org.stagecraft.player.wire.MessageType.REQ;

import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.Bbox3d;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 62, "ranger": lasers, sonar rings, IR arrays (062_ranger.def, Player 3.1). */
public final class Ranger {
    public static final int CODE = 62;
    /** Subtype DATA 5: the device's and its elements' poses, pushed. */
    public static final int DATA_GEOM = 5;
    /** Subtype REQ 1: asks for the geometry. */
    public static final int REQ_GET_GEOM = 1;
    /** Subtype REQ 5: asks for the scan configuration (angles, resolution, range). */
    public static final int REQ_GET_CONFIG = 5;

    private Ranger() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "ranger");
        r.register(CODE, DATA, 1, "RANGE", in -> new Values("ranges", in.uint32(), Xdr.doubles(in)));
        r.register(CODE, DATA, 2, "RANGESTAMPED", in -> Stamped.read(in, "ranges"));
        r.register(CODE, DATA, 3, "INTNS", in -> new Values("intensities", in.uint32(), Xdr.doubles(in)));
        r.register(CODE, DATA, 4, "INTNSSTAMPED", in -> Stamped.read(in, "intensities"));
        r.register(CODE, DATA, DATA_GEOM, "GEOM", Geom::read);
        r.register(CODE, REQ, REQ_GET_GEOM, "GET_GEOM", Geom::read);
        r.register(CODE, REQ, 2, "POWER", Scalar.Uint8.decoder("state"));
        r.register(CODE, REQ, 3, "INTNS", Scalar.Uint8.decoder("state"));
        r.register(CODE, REQ, 4, "SET_CONFIG", Config::read);
        r.register(CODE, REQ, REQ_GET_CONFIG, "GET_CONFIG", Config::read);
    }

    /**
     * player_ranger_data_range ({@code ranges}) or player_ranger_data_intns ({@code intensities}):
     * one double per beam or element.
     */
    public record Values(String name, int count, DoubleArray values) implements MessageBody {
        @Override
        public void encode(XdrWriter w) {
            w.uint32(count);
            Xdr.doubles(w, values);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, name + "_count", count);
            Xdr.doubles(v, name, values);
        }
    }

    /** player_ranger_geom: device pose and size, and a pose and size per element. */
    public record Geom(Pose3d pose, Bbox3d size, int elementPosesCount, List<Pose3d> elementPoses,
            int elementSizesCount, List<Bbox3d> elementSizes) implements MessageBody {
        static Geom read(XdrReader r) {
            return new Geom(Pose3d.read(r), Bbox3d.read(r), r.uint32(), Xdr.structs(r, Pose3d.XDR_SIZE, Pose3d::read),
                    r.uint32(), Xdr.structs(r, Bbox3d.XDR_SIZE, Bbox3d::read));
        }

        @Override
        public void encode(XdrWriter w) {
            pose.encode(w);
            size.encode(w);
            w.uint32(elementPosesCount);
            Xdr.structs(w, elementPoses);
            w.uint32(elementSizesCount);
            Xdr.structs(w, elementSizes);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "pose", pose);
            Xdr.struct(v, "size", size);
            Xdr.u32(v, "element_poses_count", elementPosesCount);
            Xdr.structs(v, "element_poses", elementPoses);
            Xdr.u32(v, "element_sizes_count", elementSizesCount);
            Xdr.structs(v, "element_sizes", elementSizes);
        }
    }

    /** player_ranger_config (Player 3.1 layout, with min_range). */
    public record Config(double minAngle, double maxAngle, double angularRes, double minRange, double maxRange,
            double rangeRes, double frequency) implements MessageBody {
        static Config read(XdrReader r) {
            return new Config(r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float64(minAngle).float64(maxAngle).float64(angularRes).float64(minRange).float64(maxRange)
                    .float64(rangeRes).float64(frequency);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("min_angle", minAngle);
            v.float64("max_angle", maxAngle);
            v.float64("angular_res", angularRes);
            v.float64("min_range", minRange);
            v.float64("max_range", maxRange);
            v.float64("range_res", rangeRes);
            v.float64("frequency", frequency);
        }
    }

    /** player_ranger_data_rangestamped / intnsstamped: values with optional geometry and config. */
    public record Stamped(Values data, int haveGeom, Geom geom, int haveConfig, Config config) implements MessageBody {
        static Stamped read(XdrReader r, String name) {
            return new Stamped(new Values(name, r.uint32(), Xdr.doubles(r)), r.uint8(), Geom.read(r), r.uint8(),
                    Config.read(r));
        }

        @Override
        public void encode(XdrWriter w) {
            data.encode(w);
            w.uint8(haveGeom);
            geom.encode(w);
            w.uint8(haveConfig);
            config.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "data", data);
            v.integer("have_geom", haveGeom);
            Xdr.struct(v, "geom", geom);
            v.integer("have_config", haveConfig);
            Xdr.struct(v, "config", config);
        }
    }
}
