package org.stagecraft.replay.writelog;

import org.stagecraft.player.msg.Geometry.Bbox3d;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Geometry.Pose3d;

/** The geometry values writelog writes: full 3-D poses and boxes, or the planar part only. */
final class TextGeometry {
    private TextGeometry() {
    }

    static void pose3d(TextOut out, Pose3d p) {
        out.float64(p.px()).float64(p.py()).float64(p.pz()).float64(p.proll()).float64(p.ppitch()).float64(p.pyaw());
    }

    static Pose3d pose3d(Tokens in) throws WritelogSyntaxException {
        return new Pose3d(in.float64("px"), in.float64("py"), in.float64("pz"), in.float64("proll"),
                in.float64("ppitch"), in.float64("pyaw"));
    }

    /** Width, length, height: the order ranger geometry uses. */
    static void bbox3d(TextOut out, Bbox3d b) {
        out.float64(b.sw()).float64(b.sl()).float64(b.sh());
    }

    static Bbox3d bbox3d(Tokens in) throws WritelogSyntaxException {
        return new Bbox3d(in.float64("sw"), in.float64("sl"), in.float64("sh"));
    }

    static void pose2d(TextOut out, Pose2d p) {
        out.float64(p.px()).float64(p.py()).float64(p.pa());
    }

    static Pose2d pose2d(Tokens in) throws WritelogSyntaxException {
        return new Pose2d(in.float64("px"), in.float64("py"), in.float64("pa"));
    }

    /** x, y, yaw of a 3-D pose: all writelog keeps of a sonar or bumper mount. */
    static void planar(TextOut out, Pose3d p) {
        out.float64(p.px()).float64(p.py()).float64(p.pyaw());
    }

    static Pose3d planar(Tokens in) throws WritelogSyntaxException {
        double px = in.float64("px");
        double py = in.float64("py");
        return new Pose3d(px, py, 0, 0, 0, in.float64("pyaw"));
    }

    /** A device geometry reply as writelog keeps it: x, y, yaw, length, width (no z, roll, pitch or height). */
    static void planarGeom(TextOut out, DeviceGeom g) {
        planar(out, g.pose());
        out.float64(g.size().sl()).float64(g.size().sw());
    }

    static DeviceGeom planarGeom(Tokens in) throws WritelogSyntaxException {
        Pose3d pose = planar(in);
        double sl = in.float64("length");
        double sw = in.float64("width");
        return new DeviceGeom(pose, new Bbox3d(sw, sl, 0));
    }
}
