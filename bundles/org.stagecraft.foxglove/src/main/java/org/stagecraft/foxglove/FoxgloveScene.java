package org.stagecraft.foxglove;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.zip.DataFormatException;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Blobfinder;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.MapInterface;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.spy.proxy.SpyDiagnostic;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;

/**
 * Turns what the spy publishes on the stream bus (or a log replays) into Foxglove's well-known
 * messages, for an MCAP export and the live WebSocket server alike. Feed it the bus messages in
 * time order, from one thread; it advertises each channel on the sink before its first message.
 *
 * <p>Per robot ({@link FoxgloveNames}): {@code foxglove.FrameTransform} on {@code /robotN/tf} for
 * the robot in the world (its odometry pose) and for each device on the robot (its geometry; at the
 * robot's origin until Player sent one); {@code foxglove.PoseInFrame} {@code /robotN/pose} and
 * {@code foxglove.PosesInFrame} {@code /robotN/trail}; a robot body ({@code /robotN/body}). Per
 * device: {@code foxglove.LaserScan} for lasers and laser-like rangers, {@code foxglove.SceneUpdate}
 * for sonar and ranger cones, bumpers, fiducials and blobs, {@code foxglove.Grid} for maps. The spy's
 * diagnostics and the session's events go out as {@code foxglove.Log}.
 *
 * <p>Device transforms and the body are sent again once a second with the robot's pose, so a viewer
 * that joins late or seeks finds the whole frame tree. When two robot programs read the same device
 * (two connections to one Player port), each scan reaches the spy twice: the copy with a Player
 * timestamp already sent for that device is left out.
 */
public final class FoxgloveScene {
    /** How often device transforms and bodies are repeated, and the trail sent. */
    static final long REFRESH_NANOS = 1_000_000_000L;
    /** How many past poses a trail keeps. */
    static final int TRAIL_LENGTH = 500;
    /** Stage's sonar cone (15 degrees), used until a ranger config gives the aperture. */
    static final double DEFAULT_APERTURE = Math.toRadians(15);
    /** A ranger of at most this many beams, with no geometry yet, is taken for a ring of transducers. */
    static final int MAX_RING = 32;
    /** Stage's blobfinder field of view (60 degrees): Player's blob data has no bearing, only pixels. */
    static final double BLOBFINDER_FOV = Math.toRadians(60);

    private static final int DATA = 1, RESP_ACK = 4;
    private static final int LASER_SCAN = 1, LASER_SCANPOSE = 2, RANGER_RANGE = 1, RANGER_RANGESTAMPED = 2,
            RANGER_GET_CONFIG = 5, POSITION_STATE = 1, MAP_GET_DATA = 2;
    private static final double[] BODY = { 0.8, 0.2, 0.2, 0.6 }, LASER = { 0.2, 0.4, 1, 0.25 },
            SONAR = { 0.2, 0.8, 0.3, 0.3 }, PRESSED = { 1, 0.1, 0.1, 0.9 }, RELEASED = { 0.3, 0.6, 0.3, 0.6 },
            FIDUCIAL = { 1, 0.8, 0, 0.9 };

    private final FoxgloveSink sink;
    private final Map<String, FoxgloveChannel> channels = new HashMap<>();
    private final Map<String, Robot> robots = new TreeMap<>();

    public FoxgloveScene(FoxgloveSink sink) {
        this.sink = sink;
    }

    /** One device of one robot. */
    private record Device(int interf, int index) {
    }

    /** What the scene knows of one robot. */
    private static final class Robot {
        final String name;
        final Map<Device, Placement> placements = new HashMap<>();
        final Map<Device, Ranger.Config> configs = new HashMap<>();
        final Map<Device, Bumper.Geom> bumpers = new HashMap<>();
        final Map<Device, MapState> maps = new HashMap<>();
        /** Devices whose transform was sent at least once. */
        final Map<Device, Boolean> framed = new HashMap<>();
        /** Per device and subtype: the Player timestamp and connection of the last data sent. */
        final Map<List<Integer>, double[]> lastData = new HashMap<>();
        final ArrayDeque<double[]> trail = new ArrayDeque<>();
        double x, y, yaw;
        /** Whether world -> robot was sent (the odometry pose, or the origin until one is seen). */
        boolean rooted;
        long lastRefresh = Long.MIN_VALUE;

        Robot(String name) {
            this.name = name;
        }

        Placement placement(Device d) {
            return placements.getOrDefault(d, Placement.DEFAULT);
        }
    }

    /** A map being assembled from its info and tiles. */
    private static final class MapState {
        MapInterface.@Nullable Info info;
        byte @Nullable [] cells;
    }

    /** Takes one bus message: a Player message or a spy diagnostic; anything else is ignored. */
    public void accept(StreamMessage m) {
        Object p = m.payload();
        int conn = -1;
        if (p instanceof SpyDiagnostic d) {
            diagnostic(m.timeNanos(), d);
            return;
        }
        if (p instanceof SpyMessage s) {
            conn = s.connection().id();
            p = s.message();
        }
        MessageBody body;
        double playerTime = Double.NaN;
        if (p instanceof DecodedMessage d) {
            if (d.hasProblem()) {
                return; // the spy publishes a diagnostic about it
            }
            body = d.body();
            playerTime = d.header().timestamp();
        } else if (p instanceof MessageBody b) {
            body = b;
        } else {
            return;
        }
        StreamKey k = m.key();
        boolean fromServer = k.messageType() != 2 && k.messageType() != 3;
        Robot r = robots.computeIfAbsent(FoxgloveNames.robot(fromServer ? k.source() : k.destination()), Robot::new);
        Device dev = new Device(k.deviceType(), k.index());
        long t = m.timeNanos();
        if (k.messageType() == DATA && duplicate(r, dev, k.subtype(), conn, playerTime)) {
            return;
        }
        if (k.messageType() == DATA || k.messageType() == RESP_ACK) {
            geometry(t, r, dev, body);
        }
        if (k.messageType() == RESP_ACK && k.deviceType() == Ranger.CODE && k.subtype() == RANGER_GET_CONFIG
                && body instanceof Ranger.Config c) {
            r.configs.put(dev, c);
        }
        if (k.messageType() == RESP_ACK && k.deviceType() == MapInterface.CODE) {
            map(t, r, dev, k.subtype(), body);
        }
        if (k.messageType() != DATA) {
            return;
        }
        switch (k.deviceType()) {
            case Position2d.CODE -> {
                if (k.subtype() == POSITION_STATE && body instanceof Position2d.State s) {
                    pose(t, r, dev, s);
                }
            }
            case Laser.CODE -> {
                if (k.subtype() == LASER_SCAN && body instanceof Laser.Scan s) {
                    laser(t, r, dev, s);
                } else if (k.subtype() == LASER_SCANPOSE && body instanceof Laser.ScanPose s) {
                    laser(t, r, dev, s.scan());
                }
            }
            case Ranger.CODE -> {
                if (k.subtype() == RANGER_RANGE && body instanceof Ranger.Values v) {
                    ranger(t, r, dev, v.values().toArray());
                } else if (k.subtype() == RANGER_RANGESTAMPED && body instanceof Ranger.Stamped s
                        && "ranges".equals(s.data().name())) {
                    if (s.haveConfig() != 0) {
                        r.configs.put(dev, s.config());
                    }
                    ranger(t, r, dev, s.data().values().toArray());
                }
            }
            case Sonar.CODE -> {
                if (body instanceof Sonar.Ranges s) {
                    float[] f = s.ranges().toArray();
                    double[] d = new double[f.length];
                    for (int i = 0; i < f.length; i++) {
                        d[i] = f[i];
                    }
                    cones(t, r, dev, d, DEFAULT_APERTURE);
                }
            }
            case Bumper.CODE -> {
                if (body instanceof Bumper.State s) {
                    bumpers(t, r, dev, s);
                }
            }
            case Fiducial.CODE -> {
                if (body instanceof Fiducial.Scan s) {
                    fiducials(t, r, dev, s);
                }
            }
            case Blobfinder.CODE -> {
                if (body instanceof Blobfinder.Blobs b) {
                    blobs(t, r, dev, b);
                }
            }
            case MapInterface.CODE -> map(t, r, dev, 0, body);
            default -> {
            }
        }
    }

    /** A session event (a connection opened or closed, a log imported...) as a foxglove.Log. */
    public void event(long timeNanos, String name, String text) {
        publish(FoxgloveNames.EVENTS_TOPIC, FoxgloveSchemas.LOG, timeNanos,
                FoxgloveMessages.log(timeNanos, FoxgloveMessages.INFO, name, text));
    }

    /** The robots seen so far ({@code robot6665}, ...), in name order. */
    public List<String> robots() {
        return List.copyOf(robots.keySet());
    }

    private void diagnostic(long t, SpyDiagnostic d) {
        publish(FoxgloveNames.DIAGNOSTICS_TOPIC, FoxgloveSchemas.LOG, t,
                FoxgloveMessages.log(t, FoxgloveMessages.WARNING, "spy port " + d.connection().port(), d.toString()));
    }

    private static boolean duplicate(Robot r, Device dev, int subtype, int conn, double playerTime) {
        if (Double.isNaN(playerTime) || conn < 0) {
            return false;
        }
        double @Nullable [] last = r.lastData.get(List.of(dev.interf(), dev.index(), subtype));
        if (last != null && last[1] != conn && last[0] == playerTime) {
            return true;
        }
        r.lastData.put(List.of(dev.interf(), dev.index(), subtype), new double[] { playerTime, conn });
        return false;
    }

    private void geometry(long t, Robot r, Device dev, MessageBody body) {
        Placement p = switch (body) {
            case DeviceGeom g -> Placement.of(g.pose(), g.size().sl(), g.size().sw(), g.size().sh(), List.of());
            case Ranger.Geom g when g.elementPoses().size() == 1 -> // a single-origin ranger: the scan starts at its element
                Placement.of(compose(g.pose(), g.elementPoses().get(0)), g.size().sl(), g.size().sw(), g.size().sh(),
                        List.of());
            case Ranger.Geom g -> Placement.of(g.pose(), g.size().sl(), g.size().sw(), g.size().sh(), g.elementPoses());
            case Sonar.Geom g -> Placement.of(new Pose3d(0, 0, 0, 0, 0, 0), 0, 0, 0, g.poses());
            case Fiducial.Geom g -> Placement.of(g.pose(), g.size().sl(), g.size().sw(), g.size().sh(), List.of());
            case Bumper.Geom g -> {
                r.bumpers.put(dev, g);
                yield null;
            }
            default -> null;
        };
        if (p == null) {
            return;
        }
        r.placements.put(dev, p);
        if (dev.interf() == Position2d.CODE && dev.index() == 0) {
            body(t, r);
        } else {
            deviceFrame(t, r, dev);
        }
    }

    /** {@code local} (in the frame of {@code device}) in the device's parent frame, planar with heights added. */
    private static Pose3d compose(Pose3d device, Pose3d local) {
        double c = Math.cos(Placement.sane(device.pyaw())), sn = Math.sin(Placement.sane(device.pyaw()));
        double lx = Placement.sane(local.px()), ly = Placement.sane(local.py());
        return new Pose3d(Placement.sane(device.px()) + c * lx - sn * ly, Placement.sane(device.py()) + sn * lx + c * ly,
                Placement.sane(device.pz()) + Placement.sane(local.pz()), 0, 0,
                Placement.sane(device.pyaw()) + Placement.sane(local.pyaw()));
    }

    private void pose(long t, Robot r, Device dev, Position2d.State s) {
        double x = Placement.sane(s.pos().px()), y = Placement.sane(s.pos().py()), yaw = Placement.sane(s.pos().pa());
        String frame = FoxgloveNames.deviceFrame(r.name, dev.interf(), dev.index());
        publish(FoxgloveNames.robotTopic(r.name, "tf"), FoxgloveSchemas.FRAME_TRANSFORM, t,
                FoxgloveMessages.frameTransform(t, FoxgloveNames.WORLD, frame, x, y, 0, yaw));
        if (dev.index() != 0) {
            return; // another position2d of the robot: its frame, but the robot is position2d:0
        }
        r.rooted = true;
        r.x = x;
        r.y = y;
        r.yaw = yaw;
        publish(FoxgloveNames.robotTopic(r.name, "pose"), FoxgloveSchemas.POSE_IN_FRAME, t,
                FoxgloveMessages.poseInFrame(t, FoxgloveNames.WORLD, x, y, yaw));
        double @Nullable [] last = r.trail.peekLast();
        if (last == null || Math.hypot(last[0] - x, last[1] - y) > 0.01) {
            r.trail.addLast(new double[] { x, y, yaw });
            while (r.trail.size() > TRAIL_LENGTH) {
                r.trail.removeFirst();
            }
        }
        if (r.lastRefresh == Long.MIN_VALUE || t - r.lastRefresh >= REFRESH_NANOS) {
            r.lastRefresh = t;
            publish(FoxgloveNames.robotTopic(r.name, "trail"), FoxgloveSchemas.POSES_IN_FRAME, t,
                    FoxgloveMessages.posesInFrame(t, FoxgloveNames.WORLD, new ArrayList<>(r.trail)));
            body(t, r);
            for (Device d : new ArrayList<>(r.framed.keySet())) {
                deviceFrame(t, r, d);
            }
        }
    }

    /** Until its first pose the robot stands at the origin, so that what is drawn on it is in the frame tree. */
    private void root(long t, Robot r) {
        if (!r.rooted) {
            r.rooted = true;
            publish(FoxgloveNames.robotTopic(r.name, "tf"), FoxgloveSchemas.FRAME_TRANSFORM, t,
                    FoxgloveMessages.frameTransform(t, FoxgloveNames.WORLD, r.name, 0, 0, 0, 0));
        }
    }

    /** The robot's body: a box of its position2d geometry (a Pioneer's size until one is seen). */
    private void body(long t, Robot r) {
        @Nullable Placement p = r.placements.get(new Device(Position2d.CODE, 0));
        double l = p != null && p.length() > 0 ? p.length() : 0.44, w = p != null && p.width() > 0 ? p.width() : 0.38;
        double h = p != null && p.height() > 0 ? p.height() : 0.22;
        root(t, r);
        FoxgloveMessages.Entity e = new FoxgloveMessages.Entity(t, r.name, r.name + "/body");
        e.cube(p == null ? 0 : p.x(), p == null ? 0 : p.y(), h / 2, p == null ? 0 : p.yaw(), l, w, h, BODY);
        e.text(0, 0, h + 0.2, r.name, new double[] { 1, 1, 1, 1 });
        publish(FoxgloveNames.robotTopic(r.name, "body"), FoxgloveSchemas.SCENE_UPDATE, t, e.bytes());
    }

    /** The transform from the robot to one of its devices. */
    private void deviceFrame(long t, Robot r, Device dev) {
        if (dev.interf() == Position2d.CODE) {
            return; // position2d devices are robot frames, placed by their own pose
        }
        root(t, r);
        Placement p = r.placement(dev);
        r.framed.put(dev, Boolean.TRUE);
        publish(FoxgloveNames.robotTopic(r.name, "tf"), FoxgloveSchemas.FRAME_TRANSFORM, t,
                FoxgloveMessages.frameTransform(t, r.name, FoxgloveNames.deviceFrame(r.name, dev.interf(), dev.index()),
                        p.x(), p.y(), p.z(), p.yaw()));
    }

    /** The device's frame, announced with its first data. */
    private String frameOf(long t, Robot r, Device dev) {
        if (!r.framed.containsKey(dev)) {
            deviceFrame(t, r, dev);
        }
        return FoxgloveNames.deviceFrame(r.name, dev.interf(), dev.index());
    }

    private void laser(long t, Robot r, Device dev, Laser.Scan s) {
        float[] ranges = s.ranges().toArray();
        int[] intensity = new int[s.intensity().size()];
        for (int i = 0; i < intensity.length; i++) {
            intensity[i] = s.intensity().unsigned(i);
        }
        double end = ranges.length > 1 ? s.angle(ranges.length - 1) : s.maxAngle();
        publish(FoxgloveNames.deviceTopic(r.name, dev.interf(), dev.index(), "scan"), FoxgloveSchemas.LASER_SCAN, t,
                FoxgloveMessages.laserScan(t, frameOf(t, r, dev), s.minAngle(), end, ranges, null, intensity));
    }

    /**
     * A ranger: a ring of transducers (its geometry has a pose per element) is drawn as cones; a
     * single-origin ranger (a laser) as a scan.
     */
    private void ranger(long t, Robot r, Device dev, double[] ranges) {
        Placement p = r.placement(dev);
        Ranger.@Nullable Config c = r.configs.get(dev);
        if (p.elements().size() > 1 && p.elements().size() == ranges.length) {
            double aperture = c != null && c.maxAngle() > c.minAngle() ? c.maxAngle() - c.minAngle() : DEFAULT_APERTURE;
            cones(t, r, dev, ranges, aperture);
            return;
        }
        if (!p.seen() && c == null && ranges.length <= MAX_RING) {
            return; // a sonar ring whose geometry has not come yet: no place for its cones, and no scan
        }
        double start = -Math.PI / 2, end = Math.PI / 2; // a SICK LMS200's fan until the config is seen
        if (c != null) {
            start = c.minAngle();
            end = c.angularRes() > 0 && ranges.length > 1 ? c.minAngle() + (ranges.length - 1) * c.angularRes()
                    : c.maxAngle();
        }
        publish(FoxgloveNames.deviceTopic(r.name, dev.interf(), dev.index(), "scan"), FoxgloveSchemas.LASER_SCAN, t,
                FoxgloveMessages.laserScan(t, frameOf(t, r, dev), start, end, null, ranges, new int[0]));
    }

    /** Sonar-like ranges: a cone per transducer, each at its element pose in the device frame. */
    private void cones(long t, Robot r, Device dev, double[] ranges, double aperture) {
        Placement p = r.placement(dev);
        String frame = frameOf(t, r, dev);
        int segments = 6;
        double[] xy = new double[ranges.length * segments * 6];
        int n = 0;
        for (int i = 0; i < ranges.length && i < p.elements().size(); i++) {
            double[] e = p.elements().get(i);
            double range = ranges[i];
            if (!(range > 0) || !Double.isFinite(range)) {
                continue;
            }
            for (int s = 0; s < segments; s++) {
                double a0 = e[2] - aperture / 2 + s * aperture / segments, a1 = a0 + aperture / segments;
                xy[n++] = e[0];
                xy[n++] = e[1];
                xy[n++] = e[0] + range * Math.cos(a0);
                xy[n++] = e[1] + range * Math.sin(a0);
                xy[n++] = e[0] + range * Math.cos(a1);
                xy[n++] = e[1] + range * Math.sin(a1);
            }
        }
        FoxgloveMessages.Entity en = new FoxgloveMessages.Entity(t, frame, frame + "/cones");
        en.triangles(xy, n, SONAR);
        publish(FoxgloveNames.deviceTopic(r.name, dev.interf(), dev.index(), "cones"), FoxgloveSchemas.SCENE_UPDATE, t,
                en.bytes());
    }

    /** Each bumper as a thin bar where its geometry puts it, red while pressed; nothing until the geometry is seen. */
    private void bumpers(long t, Robot r, Device dev, Bumper.State s) {
        Bumper.@Nullable Geom g = r.bumpers.get(dev);
        if (g == null) {
            return;
        }
        root(t, r);
        FoxgloveMessages.Entity e = new FoxgloveMessages.Entity(t, r.name, r.name + "/" + FoxgloveNames.device(dev.interf(), dev.index()));
        for (int i = 0; i < g.bumperDef().size(); i++) {
            Bumper.Define d = g.bumperDef().get(i);
            boolean pressed = i < s.bumpers().size() && s.bumpers().get(i) != 0;
            e.cube(Placement.sane(d.pose().px()), Placement.sane(d.pose().py()), 0.1, Placement.sane(d.pose().pyaw()), 0.03,
                    Math.max(0.02, Placement.sane(d.length())), 0.05, pressed ? PRESSED : RELEASED);
        }
        publish(FoxgloveNames.deviceTopic(r.name, dev.interf(), dev.index(), "bumpers"), FoxgloveSchemas.SCENE_UPDATE, t,
                e.bytes());
    }

    private void fiducials(long t, Robot r, Device dev, Fiducial.Scan s) {
        String frame = frameOf(t, r, dev);
        FoxgloveMessages.Entity e = new FoxgloveMessages.Entity(t, frame, frame + "/fiducials");
        for (Fiducial.Item f : s.fiducials()) {
            e.cube(Placement.sane(f.pose().px()), Placement.sane(f.pose().py()), 0.15, Placement.sane(f.pose().pyaw()), 0.1,
                    0.3, 0.3, FIDUCIAL);
        }
        for (Fiducial.Item f : s.fiducials()) {
            e.text(Placement.sane(f.pose().px()), Placement.sane(f.pose().py()), 0.45, "fiducial " + f.id(), FIDUCIAL);
        }
        publish(FoxgloveNames.deviceTopic(r.name, dev.interf(), dev.index(), "fiducials"), FoxgloveSchemas.SCENE_UPDATE,
                t, e.bytes());
    }

    /**
     * Blobs at their bearing (from the pixel column, across the camera's field of view) and range, in
     * their colour.
     */
    private void blobs(long t, Robot r, Device dev, Blobfinder.Blobs b) {
        String frame = frameOf(t, r, dev);
        FoxgloveMessages.Entity e = new FoxgloveMessages.Entity(t, frame, frame + "/blobs");
        for (Blobfinder.Blob blob : b.blobs()) {
            double bearing = b.width() > 0 ? (0.5 - (double) Integer.toUnsignedLong(blob.x()) / b.width()) * BLOBFINDER_FOV : 0;
            double range = blob.range() > 0 && Float.isFinite(blob.range()) ? blob.range() : 1;
            double size = Math.max(0.05, Math.min(1, Math.sqrt(Integer.toUnsignedLong(blob.area())) / 100.0));
            int c = blob.color();
            e.cube(range * Math.cos(bearing), range * Math.sin(bearing), size / 2, bearing, size, size, size,
                    new double[] { ((c >> 16) & 0xff) / 255.0, ((c >> 8) & 0xff) / 255.0, (c & 0xff) / 255.0, 0.9 });
        }
        publish(FoxgloveNames.deviceTopic(r.name, dev.interf(), dev.index(), "blobs"), FoxgloveSchemas.SCENE_UPDATE, t,
                e.bytes());
    }

    /** A map's info (DATA or GET_INFO reply) and its tiles (GET_DATA replies), sent as a grid in the world frame. */
    private void map(long t, Robot r, Device dev, int replySubtype, MessageBody body) {
        MapState m = r.maps.computeIfAbsent(dev, d -> new MapState());
        if (body instanceof MapInterface.Info info) {
            long cells = Integer.toUnsignedLong(info.width()) * Integer.toUnsignedLong(info.height());
            if (cells <= 0 || cells > 64L * 1024 * 1024) {
                return;
            }
            m.info = info;
            m.cells = new byte[(int) cells];
            java.util.Arrays.fill(m.cells, (byte) -1);
            return;
        }
        if (replySubtype != MAP_GET_DATA || !(body instanceof MapInterface.Tile tile) || m.info == null) {
            return;
        }
        byte[] data;
        try {
            data = tile.cells();
        } catch (DataFormatException e) {
            return;
        }
        int w = m.info.width(), h = m.info.height();
        byte[] cells = Objects.requireNonNull(m.cells); // set together with m.info
        for (int j = 0; j < tile.height(); j++) {
            for (int i = 0; i < tile.width(); i++) {
                int src = i + j * tile.width(), col = tile.col() + i, row = tile.row() + j;
                if (src < data.length && col >= 0 && col < w && row >= 0 && row < h) {
                    cells[col + row * w] = data[src] < 0 ? 0 : data[src] > 0 ? (byte) 100 : (byte) -1;
                }
            }
        }
        publish(FoxgloveNames.deviceTopic(r.name, dev.interf(), dev.index(), "grid"), FoxgloveSchemas.GRID, t,
                FoxgloveMessages.grid(t, FoxgloveNames.WORLD, m.info.origin().px(), m.info.origin().py(),
                        m.info.origin().pa(), m.info.scale(), w, cells));
    }

    private void publish(String topic, String schema, long t, byte[] json) {
        FoxgloveChannel c = channels.get(topic);
        if (c == null) {
            c = FoxgloveSchemas.channel(topic, schema);
            channels.put(topic, c);
            sink.advertise(c);
        }
        sink.publish(c, t, t, json);
    }
}
