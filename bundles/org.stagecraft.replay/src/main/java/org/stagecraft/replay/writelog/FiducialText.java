package org.stagecraft.replay.writelog;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.player.msg.Geometry.Bbox2d;
import org.stagecraft.player.msg.Geometry.Bbox3d;
import org.stagecraft.player.msg.Geometry.Pose3d;

/**
 * fiducial: detections (1:1): id, pose and pose uncertainty per marker; the geometry reply (4:1):
 * pose, length, width, height, marker length and width.
 */
final class FiducialText implements PayloadText {

    @Override
    public @Nullable String cannotWrite(int type, int subtype, MessageBody body) {
        if (type == DATA && subtype == 1 && body instanceof Fiducial.Scan) {
            return null;
        }
        if (type == RESP_ACK && subtype == 1 && body instanceof Fiducial.Geom) {
            return null;
        }
        return "writelog writes only fiducial detections and geometry";
    }

    @Override
    public void write(int type, int subtype, MessageBody body, TextOut out) {
        if (body instanceof Fiducial.Scan s) {
            out.uint32(s.fiducials().size());
            for (Fiducial.Item f : s.fiducials()) {
                out.int32(f.id());
                TextGeometry.pose3d(out, f.pose());
                TextGeometry.pose3d(out, f.upose());
            }
        } else {
            Fiducial.Geom g = (Fiducial.Geom) body;
            TextGeometry.pose3d(out, g.pose());
            out.float64(g.size().sl()).float64(g.size().sw()).float64(g.size().sh());
            out.float64(g.fiducialSize().sl()).float64(g.fiducialSize().sw());
        }
    }

    @Override
    public MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException {
        if (type == DATA && subtype == 1) {
            int n = in.count("fiducials_count", 13);
            List<Fiducial.Item> items = new ArrayList<>(n);
            for (int i = 0; i < n; i++) {
                items.add(new Fiducial.Item(in.int32("id"), TextGeometry.pose3d(in), TextGeometry.pose3d(in)));
            }
            return new Fiducial.Scan(n, items);
        }
        if (type == RESP_ACK && subtype == 1) {
            Pose3d pose = TextGeometry.pose3d(in);
            double sl = in.float64("length");
            double sw = in.float64("width");
            double sh = in.float64("height");
            double fsl = in.float64("fiducial length");
            double fsw = in.float64("fiducial width");
            return new Fiducial.Geom(pose, new Bbox3d(sw, sl, sh), new Bbox2d(fsw, fsl));
        }
        throw PayloadText.unknown("fiducial", type, subtype);
    }
}
