package org.stagecraft.replay.writelog;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.DoubleArray;
import org.stagecraft.player.msg.Geometry.Bbox3d;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.msg.Ranger;

/**
 * ranger: ranges (1:1), intensities (1:3), the geometry reply (4:1) and the config reply (4:5).
 * The stamped variants (1:2, 1:4) are read but never written: writelog writes them without the
 * have_config flag that readlog then expects, and readlog steps over every second range, so Player
 * cannot replay them either way.
 */
final class RangerText implements PayloadText {

    @Override
    public @Nullable String cannotWrite(int type, int subtype, MessageBody body) {
        if (type == DATA && (subtype == 1 || subtype == 3) && body instanceof Ranger.Values) {
            return null;
        }
        if (type == RESP_ACK && subtype == 1 && body instanceof Ranger.Geom) {
            return null;
        }
        if (type == RESP_ACK && subtype == 5 && body instanceof Ranger.Config) {
            return null;
        }
        if (type == DATA && (subtype == 2 || subtype == 4)) {
            return "Player's readlog cannot read stamped ranger data";
        }
        return "writelog writes only ranger ranges, intensities, geometry and config";
    }

    @Override
    public void write(int type, int subtype, MessageBody body, TextOut out) {
        switch (body) {
            case Ranger.Values v -> values(out, v);
            case Ranger.Geom g -> geom(out, g);
            default -> config(out, (Ranger.Config) body);
        }
    }

    private static void values(TextOut out, Ranger.Values v) {
        out.uint32(v.values().size());
        for (int i = 0; i < v.values().size(); i++) {
            out.float64(v.values().get(i));
        }
    }

    private static void geom(TextOut out, Ranger.Geom g) {
        TextGeometry.pose3d(out, g.pose());
        TextGeometry.bbox3d(out, g.size());
        out.uint32(g.elementPoses().size());
        for (Pose3d p : g.elementPoses()) {
            TextGeometry.pose3d(out, p);
        }
        out.uint32(g.elementSizes().size());
        for (Bbox3d b : g.elementSizes()) {
            TextGeometry.bbox3d(out, b);
        }
    }

    private static void config(TextOut out, Ranger.Config c) {
        out.float64(c.minAngle()).float64(c.maxAngle()).float64(c.angularRes()).float64(c.minRange())
                .float64(c.maxRange()).float64(c.rangeRes()).float64(c.frequency());
    }

    @Override
    public MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException {
        if (type == DATA && (subtype == 1 || subtype == 3)) {
            return values(in, subtype == 1 ? "ranges" : "intensities");
        }
        if (type == DATA && (subtype == 2 || subtype == 4)) {
            return stamped(in, subtype == 2 ? "ranges" : "intensities");
        }
        if (type == RESP_ACK && subtype == 1) {
            return geom(in);
        }
        if (type == RESP_ACK && subtype == 5) {
            return config(in);
        }
        throw PayloadText.unknown("ranger", type, subtype);
    }

    private static Ranger.Values values(Tokens in, String name) throws WritelogSyntaxException {
        int n = in.count(name + "_count", 1);
        double[] v = new double[n];
        for (int i = 0; i < n; i++) {
            v[i] = in.float64(name + " " + i);
        }
        return new Ranger.Values(name, n, DoubleArray.of(v));
    }

    private static Ranger.Geom geom(Tokens in) throws WritelogSyntaxException {
        Pose3d pose = TextGeometry.pose3d(in);
        Bbox3d size = TextGeometry.bbox3d(in);
        int np = in.count("element_poses_count", 6);
        List<Pose3d> poses = new ArrayList<>(np);
        for (int i = 0; i < np; i++) {
            poses.add(TextGeometry.pose3d(in));
        }
        int ns = in.count("element_sizes_count", 3);
        List<Bbox3d> sizes = new ArrayList<>(ns);
        for (int i = 0; i < ns; i++) {
            sizes.add(TextGeometry.bbox3d(in));
        }
        return new Ranger.Geom(pose, size, np, poses, ns, sizes);
    }

    private static Ranger.Config config(Tokens in) throws WritelogSyntaxException {
        return new Ranger.Config(in.float64("min_angle"), in.float64("max_angle"), in.float64("angular_res"),
                in.float64("min_range"), in.float64("max_range"), in.float64("range_res"), in.float64("frequency"));
    }

    /**
     * Player's writer puts no have_config flag before the optional config, its reader expects one; the
     * number of values left tells which of the two this line is.
     */
    private static Ranger.Stamped stamped(Tokens in, String name) throws WritelogSyntaxException {
        Ranger.Values data = values(in, name);
        int haveGeom = in.int32("have_geom") & 0xFF;
        Ranger.Geom geom = haveGeom != 0 ? geom(in)
                : new Ranger.Geom(new Pose3d(0, 0, 0, 0, 0, 0), new Bbox3d(0, 0, 0), 0, List.of(), 0, List.of());
        int haveConfig;
        switch (in.remaining()) {
            case 0 -> haveConfig = 0;
            case 7 -> haveConfig = 1;
            case 1, 8 -> haveConfig = in.int32("have_config") & 0xFF;
            default -> throw new WritelogSyntaxException(in.remaining()
                    + " values after the geometry, expected 0 or 7 (config) or 1 or 8 (have_config and config)");
        }
        Ranger.Config config = haveConfig != 0 && !in.atEnd() ? config(in) : new Ranger.Config(0, 0, 0, 0, 0, 0, 0);
        return new Ranger.Stamped(data, haveGeom, geom, haveConfig, config);
    }
}
