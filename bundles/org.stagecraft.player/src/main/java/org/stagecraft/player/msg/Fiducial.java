package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.DATA;
import static org.stagecraft.player.wire.MessageType.REQ;

import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Geometry.Bbox2d;
import org.stagecraft.player.msg.Geometry.Bbox3d;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Interface 10, "fiducial": detected markers (010_fiducial.def). */
public final class Fiducial {
    public static final int CODE = 10;
    /** Subtype REQ 1: asks for the geometry. */
    public static final int REQ_GET_GEOM = 1;

    private Fiducial() {
    }

    static void register(CodecRegistry r) {
        r.registerInterface(CODE, "fiducial");
        r.register(CODE, DATA, 1, "SCAN", Scan::read);
        r.register(CODE, REQ, REQ_GET_GEOM, "GET_GEOM", Geom::read);
        r.register(CODE, REQ, 2, "GET_FOV", Fov::read);
        r.register(CODE, REQ, 3, "SET_FOV", Fov::read);
        r.register(CODE, REQ, 7, "GET_ID", Scalar.Uint32.decoder("id"));
        r.register(CODE, REQ, 8, "SET_ID", Scalar.Uint32.decoder("id"));
    }

    /** player_fiducial_item: id (-1 when unidentified), pose relative to the detector, uncertainty. */
    public record Item(int id, Pose3d pose, Pose3d upose) implements MessageBody {
        static final int XDR_SIZE = 4 + 2 * Pose3d.XDR_SIZE;

        static Item read(XdrReader r) {
            return new Item(r.int32(), Pose3d.read(r), Pose3d.read(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.int32(id);
            pose.encode(w);
            upose.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.integer("id", id);
            Xdr.struct(v, "pose", pose);
            Xdr.struct(v, "upose", upose);
        }
    }

    /** player_fiducial_data. */
    public record Scan(int fiducialsCount, List<Item> fiducials) implements MessageBody {
        static Scan read(XdrReader r) {
            return new Scan(r.uint32(), Xdr.structs(r, Item.XDR_SIZE, Item::read));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(fiducialsCount);
            Xdr.structs(w, fiducials);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "fiducials_count", fiducialsCount);
            Xdr.structs(v, "fiducials", fiducials);
        }
    }

    /** player_fiducial_geom: detector pose and size, and the size of the markers. */
    public record Geom(Pose3d pose, Bbox3d size, Bbox2d fiducialSize) implements MessageBody {
        static Geom read(XdrReader r) {
            return new Geom(Pose3d.read(r), Bbox3d.read(r), Bbox2d.read(r));
        }

        @Override
        public void encode(XdrWriter w) {
            pose.encode(w);
            size.encode(w);
            fiducialSize.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "pose", pose);
            Xdr.struct(v, "size", size);
            Xdr.struct(v, "fiducial_size", fiducialSize);
        }
    }

    /** player_fiducial_fov: the sensor's field of view. */
    public record Fov(float minRange, float maxRange, float viewAngle) implements MessageBody {
        static Fov read(XdrReader r) {
            return new Fov(r.float32(), r.float32(), r.float32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float32(minRange).float32(maxRange).float32(viewAngle);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float32("min_range", minRange);
            v.float32("max_range", maxRange);
            v.float32("view_angle", viewAngle);
        }
    }
}
