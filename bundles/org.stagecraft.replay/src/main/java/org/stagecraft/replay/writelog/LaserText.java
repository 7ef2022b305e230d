package org.stagecraft.replay.writelog;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Laser;

/**
 * laser: scans (1:1), scans with a pose (1:2) and the geometry reply (4:1). Each range is followed by
 * its intensity (zero where the scan has none), so readlog always has as many intensities as ranges;
 * see {@link LineNote} for how Stagecraft's own files keep a scan without intensities exact.
 * Scans with explicit angles (1:3) are skipped: writelog writes them but readlog cannot read them.
 */
final class LaserText implements PayloadText {

    @Override
    public @Nullable String cannotWrite(int type, int subtype, MessageBody body) {
        if (type == DATA && subtype == 1 && body instanceof Laser.Scan) {
            return null;
        }
        if (type == DATA && subtype == 2 && body instanceof Laser.ScanPose) {
            return null;
        }
        if (type == RESP_ACK && subtype == 1 && body instanceof DeviceGeom) {
            return null;
        }
        if (type == DATA && subtype == 3) {
            return "Player's readlog cannot read laser scans with angles (SCANANGLE)";
        }
        return "writelog writes only laser scans and geometry";
    }

    @Override
    public LineNote noteFor(MessageBody body) {
        Laser.Scan s = body instanceof Laser.ScanPose p ? p.scan() : body instanceof Laser.Scan l ? l : null;
        return s != null && s.intensityCount() == 0 && s.intensity().size() == 0 && s.ranges().size() > 0
                ? LineNote.NO_INTENSITIES : LineNote.NONE;
    }

    @Override
    public void write(int type, int subtype, MessageBody body, TextOut out) {
        switch (body) {
            case Laser.Scan s -> {
                out.uint32(s.id());
                scan(out, s);
            }
            case Laser.ScanPose p -> {
                out.uint32(p.scan().id());
                TextGeometry.pose2d(out, p.pose());
                scan(out, p.scan());
            }
            default -> TextGeometry.planarGeom(out, (DeviceGeom) body);
        }
    }

    private static void scan(TextOut out, Laser.Scan s) {
        out.float32(s.minAngle()).float32(s.maxAngle()).float32(s.resolution()).float32(s.maxRange());
        int n = s.ranges().size();
        out.uint32(n);
        for (int i = 0; i < n; i++) {
            out.float32(s.ranges().get(i));
            out.int32(i < s.intensity().size() ? s.intensity().unsigned(i) : 0);
        }
    }

    @Override
    public MessageBody read(int type, int subtype, Tokens in, LineNote note) throws WritelogSyntaxException {
        if (type == DATA && subtype == 1) {
            int id = in.int32("scan id");
            return scan(in, id, note);
        }
        if (type == DATA && subtype == 2) {
            int id = in.int32("scan id");
            var pose = TextGeometry.pose2d(in);
            return new Laser.ScanPose(scan(in, id, note), pose);
        }
        if (type == RESP_ACK && subtype == 1) {
            return TextGeometry.planarGeom(in);
        }
        throw PayloadText.unknown("laser", type, subtype);
    }

    private static Laser.Scan scan(Tokens in, int id, LineNote note) throws WritelogSyntaxException {
        float min = in.float32("min_angle");
        float max = in.float32("max_angle");
        float res = in.float32("resolution");
        float maxRange = in.float32("max_range");
        int n = in.count("ranges_count", 2);
        float[] ranges = new float[n];
        byte[] intensity = new byte[n];
        for (int i = 0; i < n; i++) {
            ranges[i] = in.float32("range " + i);
            intensity[i] = (byte) in.int32("intensity " + i);
        }
        boolean none = note == LineNote.NO_INTENSITIES && allZero(intensity);
        return new Laser.Scan(min, max, res, maxRange, n, FloatArray.of(ranges), none ? 0 : n,
                none ? ByteArray.EMPTY : ByteArray.of(intensity), id);
    }

    private static boolean allZero(byte[] b) {
        for (byte x : b) {
            if (x != 0) {
                return false;
            }
        }
        return true;
    }
}
