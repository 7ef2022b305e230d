package org.stagecraft.player.msg;

import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Player's shared geometry and addressing structs (player.h). */
public final class Geometry {
    private Geometry() {
    }

    /** player_pose2d: x, y [m], yaw [rad]. */
    public record Pose2d(double px, double py, double pa) implements MessageBody {
        public static final int XDR_SIZE = 24;

        public static Pose2d read(XdrReader r) {
            return new Pose2d(r.float64(), r.float64(), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float64(px).float64(py).float64(pa);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("px", px);
            v.float64("py", py);
            v.float64("pa", pa);
        }
    }

    /** player_pose3d: x, y, z [m], roll, pitch, yaw [rad]. */
    public record Pose3d(double px, double py, double pz, double proll, double ppitch, double pyaw)
            implements MessageBody {
        public static final int XDR_SIZE = 48;

        public static Pose3d read(XdrReader r) {
            return new Pose3d(r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float64(px).float64(py).float64(pz).float64(proll).float64(ppitch).float64(pyaw);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("px", px);
            v.float64("py", py);
            v.float64("pz", pz);
            v.float64("proll", proll);
            v.float64("ppitch", ppitch);
            v.float64("pyaw", pyaw);
        }
    }

    /** player_bbox2d: width and length [m]. */
    public record Bbox2d(double sw, double sl) implements MessageBody {
        public static Bbox2d read(XdrReader r) {
            return new Bbox2d(r.float64(), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float64(sw).float64(sl);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("sw", sw);
            v.float64("sl", sl);
        }
    }

    /** player_bbox3d: width, length, height [m]. */
    public record Bbox3d(double sw, double sl, double sh) implements MessageBody {
        public static final int XDR_SIZE = 24;

        public static Bbox3d read(XdrReader r) {
            return new Bbox3d(r.float64(), r.float64(), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float64(sw).float64(sl).float64(sh);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("sw", sw);
            v.float64("sl", sl);
            v.float64("sh", sh);
        }
    }

    /** player_segment: a line segment [m]. */
    public record Segment(double x0, double y0, double x1, double y1) implements MessageBody {
        public static Segment read(XdrReader r) {
            return new Segment(r.float64(), r.float64(), r.float64(), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.float64(x0).float64(y0).float64(x1).float64(y1);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.float64("x0", x0);
            v.float64("y0", y0);
            v.float64("x1", x1);
            v.float64("y1", y1);
        }
    }

    /** player_devaddr: which device a message or request is about. */
    public record DevAddr(int host, int robot, int interf, int index) implements MessageBody {
        public static final int XDR_SIZE = 16;

        public static DevAddr read(XdrReader r) {
            return new DevAddr(r.uint32(), r.uint32(), r.uint16(), r.uint16());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(host).uint32(robot).uint16(interf).uint16(index);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "host", host);
            Xdr.u32(v, "robot", robot);
            v.integer("interf", interf);
            v.integer("index", index);
        }
    }

    /**
     * A device's pose in robot coordinates and its size: the reply to GET_GEOM of position2d,
     * laser and others (player_position2d_geom, player_laser_geom, ...).
     */
    public record DeviceGeom(Pose3d pose, Bbox3d size) implements MessageBody {
        public static DeviceGeom read(XdrReader r) {
            return new DeviceGeom(Pose3d.read(r), Bbox3d.read(r));
        }

        @Override
        public void encode(XdrWriter w) {
            pose.encode(w);
            size.encode(w);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.struct(v, "pose", pose);
            Xdr.struct(v, "size", size);
        }
    }
}
