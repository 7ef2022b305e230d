package org.stagecraft.replay.writelog;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.msg.Sonar;

/** sonar: ranges (1:1), geometry as data (1:2) and as the geometry reply (4:1), x, y, yaw per transducer. */
final class SonarText implements PayloadText {

    @Override
    public @Nullable String cannotWrite(int type, int subtype, MessageBody body) {
        if (type == DATA && subtype == 1 && body instanceof Sonar.Ranges) {
            return null;
        }
        if ((type == DATA && subtype == 2 || type == RESP_ACK && subtype == 1) && body instanceof Sonar.Geom) {
            return null;
        }
        return "writelog writes only sonar ranges and geometry";
    }

    @Override
    public void write(int type, int subtype, MessageBody body, TextOut out) {
        if (body instanceof Sonar.Ranges r) {
            out.uint32(r.ranges().size());
            for (int i = 0; i < r.ranges().size(); i++) {
                out.float32(r.ranges().get(i));
            }
        } else {
            Sonar.Geom g = (Sonar.Geom) body;
            out.uint32(g.poses().size());
            for (Pose3d p : g.poses()) {
                TextGeometry.planar(out, p);
            }
        }
    }

    @Override
    public MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException {
        if (type == DATA && subtype == 1) {
            int n = in.count("ranges_count", 1);
            float[] r = new float[n];
            for (int i = 0; i < n; i++) {
                r[i] = in.float32("range " + i);
            }
            return new Sonar.Ranges(n, FloatArray.of(r));
        }
        if (type == DATA && subtype == 2 || type == RESP_ACK && subtype == 1) {
            int n = in.count("poses_count", 3);
            List<Pose3d> poses = new ArrayList<>(n);
            for (int i = 0; i < n; i++) {
                poses.add(TextGeometry.planar(in));
            }
            return new Sonar.Geom(n, poses);
        }
        throw PayloadText.unknown("sonar", type, subtype);
    }
}
