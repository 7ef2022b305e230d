package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.DATA;
import static org.stagecraft.player.wire.MessageType.REQ;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 6, "laser": single-origin scanning range finders (006_laser.def). */
public final class Laser {
    public static final int CODE = 6;
    /** Subtype REQ 1: asks for the geometry. */
    public static final int REQ_GET_GEOM = 1;

    private Laser() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "laser");
        r.register(CODE, DATA, 1, "SCAN", Scan::read);
        r.register(CODE, DATA, 2, "SCANPOSE", ScanPose::read);
        r.register(CODE, DATA, 3, "SCANANGLE", ScanAngle::read);
        r.register(CODE, REQ, REQ_GET_GEOM, "GET_GEOM", DeviceGeom::read);
        r.register(CODE, REQ, 2, "SET_CONFIG", Config::read);
        r.register(CODE, REQ, 3, "GET_CONFIG", Config::read);
        r.register(CODE, REQ, 4, "POWER", Scalar.Uint8.decoder("state"));
        r.register(CODE, REQ, 5, "GET_ID", Scalar.Uint32.decoder("serial_number"));
        r.register(CODE, REQ, 6, "SET_FILTER", SetFilter::read);
    }

    /** player_laser_data: a scan, counter-clockwise from min_angle in steps of resolution. */
    public record Scan(float minAngle, float maxAngle, float resolution, float maxRange, int rangesCount,
            FloatArray ranges, int intensityCount, ByteArray intensity, int id) implements MessageBody {

        static Scan read(XdrReader r) {
            return new Scan(r.float32(), r.float32(), r.float32(), r.float32(), r.uint32(), Xdr.floats(r), r.uint32(),
                    Xdr.bytes(r), r.uint32());
        }

        /** Bearing of beam i [rad]. */
        public double angle(int i) {
            return minAngle + (double) i * resolution;
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(minAngle).float32(maxAngle).float32(resolution).float32(maxRange).uint32(rangesCount);
            Xdr.floats(w, ranges);
            w.uint32(intensityCount);
            Xdr.bytes(w, intensity);
            w.uint32(id);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("min_angle", minAngle);
            v.float32("max_angle", maxAngle);
            v.float32("resolution", resolution);
            v.float32("max_range", maxRange);
            Xdr.u32(v, "ranges_count", rangesCount);
            Xdr.floats(v, "ranges", ranges);
            Xdr.u32(v, "intensity_count", intensityCount);
            Xdr.uint8s(v, "intensity", intensity);
            Xdr.u32(v, "id", id);
        }
    }

    /** player_laser_data_scanpose: a scan with the laser's global pose. */
    public record ScanPose(Scan scan, Pose2d pose) implements MessageBody {
        static ScanPose read(XdrReader r) {
            return new ScanPose(Scan.read(r), Pose2d.read(r));
        }

        @Override
        public void encode(XdrWriter w) {
            scan.encode(w);
            pose.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "scan", scan);
            Xdr.struct(v, "pose", pose);
        }
    }

    /** player_laser_data_scanangle: ranges with an explicit angle each. */
    public record ScanAngle(float maxRange, int rangesCount, FloatArray ranges, int anglesCount, FloatArray angles,
            int intensityCount, ByteArray intensity, int id) implements MessageBody {
        static ScanAngle read(XdrReader r) {
            return new ScanAngle(r.float32(), r.uint32(), Xdr.floats(r), r.uint32(), Xdr.floats(r), r.uint32(),
                    Xdr.bytes(r), r.uint32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(maxRange).uint32(rangesCount);
            Xdr.floats(w, ranges);
            w.uint32(anglesCount);
            Xdr.floats(w, angles);
            w.uint32(intensityCount);
            Xdr.bytes(w, intensity);
            w.uint32(id);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("max_range", maxRange);
            Xdr.u32(v, "ranges_count", rangesCount);
            Xdr.floats(v, "ranges", ranges);
            Xdr.u32(v, "angles_count", anglesCount);
            Xdr.floats(v, "angles", angles);
            Xdr.u32(v, "intensity_count", intensityCount);
            Xdr.uint8s(v, "intensity", intensity);
            Xdr.u32(v, "id", id);
        }
    }

    /** player_laser_config. */
    public record Config(float minAngle, float maxAngle, float resolution, float maxRange, float rangeRes,
            int intensity, float scanningFrequency) implements MessageBody {
        static Config read(XdrReader r) {
            return new Config(r.float32(), r.float32(), r.float32(), r.float32(), r.float32(), r.uint8(), r.float32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(minAngle).float32(maxAngle).float32(resolution).float32(maxRange).float32(rangeRes).uint8(intensity)
                    .float32(scanningFrequency);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("min_angle", minAngle);
            v.float32("max_angle", maxAngle);
            v.float32("resolution", resolution);
            v.float32("max_range", maxRange);
            v.float32("range_res", rangeRes);
            v.integer("intensity", intensity);
            v.float32("scanning_frequency", scanningFrequency);
        }
    }

    /** player_laser_set_filter_config. */
    public record SetFilter(int filterType, int parametersCount, FloatArray parameters) implements MessageBody {
        static SetFilter read(XdrReader r) {
            return new SetFilter(r.uint8(), r.uint32(), Xdr.floats(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint8(filterType).uint32(parametersCount);
            Xdr.floats(w, parameters);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.integer("filter_type", filterType);
            Xdr.u32(v, "parameters_count", parametersCount);
            Xdr.floats(v, "parameters", parameters);
        }
    }
}
