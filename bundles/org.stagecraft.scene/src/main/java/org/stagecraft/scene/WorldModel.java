package org.stagecraft.scene;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;

/**
 * What a Robot View knows about the world: each robot's pose (position2d state), its trail, and where its
 * devices are mounted (the geometry replies seen on the wire, defaults until then). Fed from bus threads,
 * read by the renderer on the UI thread: every accessor returns an immutable snapshot.
 *
 * <p>A robot whose program disconnected ({@link #released}) stays as it was last seen, for the user to look
 * at; once a new robot appears (the next session: its ports are new) the ended robots are forgotten, with
 * their trails and mounts, so one session's robots do not clutter the next one's view
 * ({@link #forgetting()} counts those moments, for views to frame the new robots and drop old data).
 */
public final class WorldModel {
    private static final int DATA = MessageType.DATA.code(), RESP_ACK = MessageType.RESP_ACK.code();

    private final int trailLength;
    private final Map<RobotId, Track> robots = new ConcurrentHashMap<>();
    private final Map<DeviceAddress, Mount> mounts = new ConcurrentHashMap<>();
    private final Map<DeviceAddress, RangerConfig> configs = new ConcurrentHashMap<>();
    private final Map<DeviceAddress, MessageBody> geometries = new ConcurrentHashMap<>();
    private final AtomicLong version = new AtomicLong();
    /**
     * The pose streams the bus released (their connection closed). A robot has ended when the stream of its
     * newest pose is among them; the release and the last poses come on different bus threads, in either order.
     */
    private final Set<StreamKey> releasedPoses = ConcurrentHashMap.newKeySet();
    /** Robots forgotten when a new one came; a forgotten robot that comes back is a new robot. */
    private final Set<RobotId> forgotten = ConcurrentHashMap.newKeySet();
    private final AtomicLong forgetting = new AtomicLong();

    /** @param trailLength how many past poses each robot keeps for its trail */
    public WorldModel(int trailLength) {
        this.trailLength = trailLength;
    }

    public WorldModel() {
        this(200);
    }

    /** Takes what it needs from a bus message (pose, geometry, ranger config); true if anything changed. */
    public boolean accept(StreamMessage m) {
        MessageBody body = Payloads.body(m);
        if (body == null) {
            return false;
        }
        StreamKey k = m.key();
        DeviceAddress dev = DeviceAddress.of(k);
        boolean changed = false;
        if (isGeometry(k)) {
            geometries.put(dev, body);
        }
        if (k.messageType() == DATA && k.deviceType() == Position2d.CODE && k.subtype() == Position2d.DATA_STATE
                && body instanceof Position2d.State s) {
            arrive(dev.robot()).pose(s, k, trailLength);
            changed = true;
        } else if (isGeometry(k) && body instanceof DeviceGeom g) {
            mounts.put(dev, new Mount(Pose2.of(g.pose()), finite(g.size().sl()), finite(g.size().sw()), List.of(), true));
            if (k.deviceType() == Position2d.CODE) {
                arrive(dev.robot());
            }
            changed = true;
        } else if (isGeometry(k) && body instanceof Ranger.Geom g) {
            mounts.put(dev, new Mount(Pose2.of(g.pose()), finite(g.size().sl()), finite(g.size().sw()),
                    poses(g.elementPoses()), true));
            changed = true;
        } else if (isGeometry(k) && body instanceof Sonar.Geom g) {
            mounts.put(dev, new Mount(Pose2.ORIGIN, 0, 0, poses(g.poses()), true));
            changed = true;
        } else if (isGeometry(k) && body instanceof Fiducial.Geom g) {
            mounts.put(dev, new Mount(Pose2.of(g.pose()), finite(g.size().sl()), finite(g.size().sw()), List.of(), true));
            changed = true;
        } else if (isGeometry(k)) {
            changed = true; // e.g. bumper geometry: kept as it came, see geometry()
        } else if (k.messageType() == RESP_ACK && k.deviceType() == Ranger.CODE && k.subtype() == Ranger.REQ_GET_CONFIG
                && body instanceof Ranger.Config c) {
            configs.put(dev, new RangerConfig(c.minAngle(), c.maxAngle(), c.angularRes(), c.minRange(), c.maxRange(), true));
            changed = true;
        }
        if (changed) {
            version.incrementAndGet();
        }
        return changed;
    }

    /** The robot's track; a robot new to the model first makes it forget the robots that ended. */
    private Track arrive(RobotId id) {
        Track t = robots.get(id);
        if (t != null) {
            return t;
        }
        forgotten.remove(id);
        Set<RobotId> gone = Set.copyOf(robots.keySet().stream().filter(this::ended).toList());
        if (!gone.isEmpty()) {
            for (RobotId g : gone) {
                Track old = robots.remove(g);
                if (old != null) {
                    releasedPoses.removeAll(old.poseKeys());
                }
            }
            mounts.keySet().removeIf(d -> gone.contains(d.robot()));
            configs.keySet().removeIf(d -> gone.contains(d.robot()));
            geometries.keySet().removeIf(d -> gone.contains(d.robot()));
            forgotten.addAll(gone);
            forgetting.incrementAndGet();
        }
        return robots.computeIfAbsent(id, Track::new);
    }

    /**
     * The connections of these streams closed (the bus released them): a robot whose position2d state
     * stream is among them has ended, unless it sends a pose again. It stays drawn until a new robot comes.
     */
    public void released(Set<StreamKey> keys) {
        boolean any = false;
        for (StreamKey k : keys) {
            if (k.messageType() == DATA && k.deviceType() == Position2d.CODE && k.subtype() == Position2d.DATA_STATE) {
                any |= releasedPoses.add(k);
            }
        }
        if (any) {
            version.incrementAndGet();
        }
    }

    /**
     * Whether the robot's program disconnected: the stream of its newest pose was released (it is drawn as
     * last seen until a new robot comes). A pose from another connection (another program on the same robot)
     * makes it live again.
     */
    public boolean ended(RobotId id) {
        Track t = robots.get(id);
        StreamKey last = t == null ? null : t.lastPoseKey();
        return last != null && releasedPoses.contains(last);
    }

    /** Whether the robot was forgotten when a newer one came: its data is an earlier session's. */
    public boolean forgotten(RobotId id) {
        return forgotten.contains(id);
    }

    /** How many times a new robot made the model forget ended ones (a new session began). */
    public long forgetting() {
        return forgetting.get();
    }

    /** GET_GEOM replies of any device, and the geometry DATA messages of position2d, sonar and ranger. */
    static boolean isGeometry(StreamKey k) {
        int dev = k.deviceType(), subtype = k.subtype();
        if (k.messageType() == RESP_ACK) {
            return (dev == Position2d.CODE && subtype == Position2d.REQ_GET_GEOM)
                    || (dev == Laser.CODE && subtype == Laser.REQ_GET_GEOM)
                    || (dev == Ranger.CODE && subtype == Ranger.REQ_GET_GEOM)
                    || (dev == Sonar.CODE && subtype == Sonar.REQ_GET_GEOM)
                    || (dev == Fiducial.CODE && subtype == Fiducial.REQ_GET_GEOM)
                    || (dev == Bumper.CODE && subtype == Bumper.REQ_GET_GEOM);
        }
        return k.messageType() == DATA && ((dev == Position2d.CODE && subtype == Position2d.DATA_GEOM)
                || (dev == Sonar.CODE && subtype == Sonar.DATA_GEOM)
                || (dev == Ranger.CODE && subtype == Ranger.DATA_GEOM));
    }

    /** Incremented by every change: a renderer rebuilds only when this or its data moved. */
    public long version() {
        return version.get();
    }

    /** Every robot seen so far (by position2d data or geometry), in address order. */
    public List<RobotState> robots() {
        Map<RobotId, RobotState> sorted = new TreeMap<>();
        robots.forEach((id, t) -> sorted.put(id, t.snapshot(mount(new DeviceAddress(id, Position2d.CODE, 0)))));
        return List.copyOf(sorted.values());
    }

    /** The robot's state; a robot never seen stands at the origin. */
    public RobotState robot(RobotId id) {
        @Nullable Track t = robots.get(id);
        Mount body = mount(new DeviceAddress(id, Position2d.CODE, 0));
        return t == null ? new RobotState(id, Pose2.ORIGIN, Pose2.ORIGIN, false, List.of(), body, false) : t.snapshot(body);
    }

    /** Where the device is on its robot: the geometry seen on the wire, or {@link Mount#DEFAULT}. */
    public Mount mount(DeviceAddress dev) {
        return mounts.getOrDefault(dev, Mount.DEFAULT);
    }

    /** The device's last geometry message as decoded (e.g. Bumper.Geom), or null if none was seen. */
    public @Nullable MessageBody geometry(DeviceAddress dev) {
        return geometries.get(dev);
    }

    public RangerConfig rangerConfig(DeviceAddress dev) {
        return configs.getOrDefault(dev, RangerConfig.DEFAULT_FAN);
    }

    /** The device's pose in the world: robot pose composed with the mount pose. */
    public Pose2 devicePose(DeviceAddress dev) {
        return robot(dev.robot()).pose().compose(mount(dev).pose());
    }

    private static List<Pose2> poses(List<Pose3d> ps) {
        List<Pose2> out = new ArrayList<>(ps.size());
        for (Pose3d p : ps) {
            out.add(Pose2.of(p));
        }
        return out;
    }

    // Stage's position2d geometry has uninitialised doubles (README quirk 4); sizes must stay sane.
    private static double finite(double v) {
        return Double.isFinite(v) && Math.abs(v) < 1e6 ? Math.abs(v) : 0;
    }

    private static final class Track {
        private final RobotId id;
        private final ArrayDeque<Pose2> trail = new ArrayDeque<>();
        private Pose2 pose = Pose2.ORIGIN, velocity = Pose2.ORIGIN;
        private boolean stall, seen;
        private @Nullable StreamKey lastPoseKey;
        private final Set<StreamKey> poseKeys = new java.util.HashSet<>();

        Track(RobotId id) {
            this.id = id;
        }

        synchronized @Nullable StreamKey lastPoseKey() {
            return lastPoseKey;
        }

        synchronized Set<StreamKey> poseKeys() {
            return Set.copyOf(poseKeys);
        }

        synchronized void pose(Position2d.State s, StreamKey key, int trailLength) {
            lastPoseKey = key;
            poseKeys.add(key);
            pose = Pose2.of(s.pos());
            velocity = Pose2.of(s.vel());
            stall = s.stall() != 0;
            seen = true;
            @Nullable Pose2 last = trail.peekLast();
            // a robot standing still adds nothing to its trail
            if (last == null || Math.hypot(last.x() - pose.x(), last.y() - pose.y()) > 0.01) {
                trail.addLast(pose);
                while (trail.size() > trailLength) {
                    trail.removeFirst();
                }
            }
        }

        synchronized RobotState snapshot(Mount body) {
            return new RobotState(id, pose, velocity, stall, List.copyOf(trail), body, seen);
        }
    }
}
