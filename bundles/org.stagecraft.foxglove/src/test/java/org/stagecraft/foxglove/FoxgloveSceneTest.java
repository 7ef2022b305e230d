package org.stagecraft.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.DoubleArray;
import org.stagecraft.player.msg.Geometry.Bbox3d;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Geometry.Pose3d;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyDiagnostic;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamMessage;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The scene on messages built here the way the spy publishes them. The corpus (one robot per
 * recording) is exported and checked in org.stagecraft.replay's export tests; no recording of
 * several robots exists, so the six-robot case is made here: six Player ports, as Stage's
 * six-robots.cfg serves them, each robot with a pose, a laser and a sonar ring.
 */
class FoxgloveSceneTest {
    private static final long T0 = 1_795_315_969_000_000_000L;

    /** What a sink received, in order. */
    static final class Recorded implements FoxgloveSink {
        final Map<String, FoxgloveChannel> channels = new LinkedHashMap<>();
        final List<String> topics = new ArrayList<>();
        final List<JsonObject> messages = new ArrayList<>();
        final List<Long> times = new ArrayList<>();

        @Override
        public void advertise(FoxgloveChannel c) {
            assertTrue(channels.put(c.topic(), c) == null, "advertised twice: " + c.topic());
        }

        @Override
        public void publish(FoxgloveChannel c, long log, long publish, byte[] json) {
            assertTrue(channels.get(c.topic()) == c, "published before advertised: " + c.topic());
            topics.add(c.topic());
            times.add(log);
            messages.add(JsonParser.parseString(new String(json, StandardCharsets.UTF_8)).getAsJsonObject());
        }

        List<JsonObject> of(String schema) {
            List<JsonObject> out = new ArrayList<>();
            for (int i = 0; i < topics.size(); i++) {
                if (channels.get(topics.get(i)).schemaName().equals(schema)) {
                    out.add(messages.get(i));
                }
            }
            return out;
        }
    }

    private static StreamMessage fromServer(ConnectionInfo c, long t, int interf, int index, int type, int subtype,
            double playerTime, MessageBody body) {
        MessageHeader h = new MessageHeader(0, 0, interf, index, type, subtype, playerTime, 0, 0);
        return new StreamMessage(SpyStreams.messageKey(c, Direction.SERVER_TO_CLIENT, h), t,
                new SpyMessage(c, Direction.SERVER_TO_CLIENT, 0, new DecodedMessage(h, body, null)));
    }

    private static Pose3d pose3(double x, double y, double yaw) {
        return new Pose3d(x, y, 0, 0, 0, yaw);
    }

    /** One robot's traffic at time t: geometry once, then pose, laser scan and sonar ranges. */
    private static List<StreamMessage> robot(ConnectionInfo c, long t, int step) {
        List<StreamMessage> out = new ArrayList<>();
        double sim = step * 0.1;
        if (step == 0) {
            out.add(fromServer(c, t, Position2d.CODE, 0, 4, 1, sim, new DeviceGeom(pose3(0, 0, 0), new Bbox3d(0.38, 0.44, 0.22))));
            out.add(fromServer(c, t, Laser.CODE, 0, 4, 1, sim, new DeviceGeom(pose3(0.03, 0, 0), new Bbox3d(0.1, 0.1, 0.1))));
            List<Pose3d> ring = new ArrayList<>();
            for (int i = 0; i < 16; i++) {
                ring.add(pose3(0.2 * Math.cos(i * Math.PI / 8), 0.2 * Math.sin(i * Math.PI / 8), i * Math.PI / 8));
            }
            out.add(fromServer(c, t, Ranger.CODE, 0, 4, 1, sim,
                    new Ranger.Geom(pose3(0, 0, 0), new Bbox3d(0, 0, 0), 16, ring, 0, List.of())));
        }
        out.add(fromServer(c, t, Position2d.CODE, 0, 1, 1, sim,
                new Position2d.State(new Pose2d(c.port() - 6665 + 0.1 * step, 2, 0.5), new Pose2d(0.1, 0, 0), 0)));
        float[] ranges = new float[181];
        java.util.Arrays.fill(ranges, 3.5f);
        out.add(fromServer(c, t, Laser.CODE, 0, 1, 1, sim, new Laser.Scan((float) -Math.PI / 2, (float) Math.PI / 2,
                (float) (Math.PI / 180), 8, 181, FloatArray.of(ranges), 0, ByteArray.EMPTY, step)));
        double[] sonar = new double[16];
        java.util.Arrays.fill(sonar, 1.5);
        out.add(fromServer(c, t, Ranger.CODE, 0, 1, 1, sim, new Ranger.Values("ranges", 16, DoubleArray.of(sonar))));
        return out;
    }

    private static ConnectionInfo connection(int id, int port) {
        return new ConnectionInfo(id, port, "127.0.0.1:" + (40000 + id), "127.0.0.1:" + port, "127.0.0.1:" + (port + 1000));
    }

    private static Recorded sixRobots(int steps) {
        Recorded sink = new Recorded();
        FoxgloveScene scene = new FoxgloveScene(sink);
        for (int step = 0; step < steps; step++) {
            for (int r = 0; r < 6; r++) {
                for (StreamMessage m : robot(connection(r + 1, 6665 + r), T0 + step * 100_000_000L + r * 1000, step)) {
                    scene.accept(m);
                }
            }
        }
        return sink;
    }

    @Test
    void sixRobotsOnSixPortsAreSixRobotsWithTheirOwnFrames() {
        Recorded sink = sixRobots(30);
        Set<String> robotFrames = new TreeSet<>();
        for (JsonObject tf : sink.of(FoxgloveSchemas.FRAME_TRANSFORM)) {
            if (tf.get("parent_frame_id").getAsString().equals(FoxgloveNames.WORLD)) {
                robotFrames.add(tf.get("child_frame_id").getAsString());
            }
        }
        assertEquals(Set.of("robot6665", "robot6666", "robot6667", "robot6668", "robot6669", "robot6670"), robotFrames);
        Set<String> scanTopics = new TreeSet<>(), poseTopics = new TreeSet<>();
        for (String t : sink.channels.keySet()) {
            String schema = sink.channels.get(t).schemaName();
            if (schema.equals(FoxgloveSchemas.LASER_SCAN)) {
                scanTopics.add(t);
            } else if (schema.equals(FoxgloveSchemas.POSE_IN_FRAME)) {
                poseTopics.add(t);
            }
        }
        assertEquals(6, scanTopics.size(), scanTopics.toString());
        assertEquals(6, poseTopics.size(), poseTopics.toString());
        // each robot's pose is its own: robot k stands at x = k + 0.1 * step
        for (JsonObject p : sink.of(FoxgloveSchemas.POSE_IN_FRAME)) {
            assertEquals(FoxgloveNames.WORLD, p.get("frame_id").getAsString());
        }
        assertFramesChainToWorld(sink);
    }

    @Test
    void sonarRingIsConesAndLaserIsAScanAtTheDevicesGeometry() {
        Recorded sink = sixRobots(3);
        JsonObject laserTf = null;
        for (JsonObject tf : sink.of(FoxgloveSchemas.FRAME_TRANSFORM)) {
            if (tf.get("child_frame_id").getAsString().equals("robot6665/laser0")) {
                laserTf = tf;
            }
        }
        assertNotNull(laserTf);
        assertEquals("robot6665", laserTf.get("parent_frame_id").getAsString());
        assertEquals(0.03, laserTf.getAsJsonObject("translation").get("x").getAsDouble(), 1e-12);
        assertTrue(sink.channels.containsKey("/robot6665/ranger0/cones"));
        assertTrue(!sink.channels.containsKey("/robot6665/ranger0/scan"), "a sonar ring is not a scan");
        JsonObject cones = sink.of(FoxgloveSchemas.SCENE_UPDATE).stream()
                .filter(m -> m.getAsJsonArray("entities").get(0).getAsJsonObject().get("id").getAsString()
                        .equals("robot6665/ranger0/cones"))
                .findFirst().orElseThrow();
        // 16 transducers, 6 slices of 3 points each
        assertEquals(16 * 6 * 3, cones.getAsJsonArray("entities").get(0).getAsJsonObject().getAsJsonArray("triangles")
                .get(0).getAsJsonObject().getAsJsonArray("points").size());
        JsonObject scan = sink.of(FoxgloveSchemas.LASER_SCAN).get(0);
        assertEquals(181, scan.getAsJsonArray("ranges").size());
        assertEquals(-Math.PI / 2, scan.get("start_angle").getAsDouble(), 1e-6);
        assertEquals(Math.PI / 2, scan.get("end_angle").getAsDouble(), 1e-6);
    }

    @Test
    void theSameScanSeenByTwoConnectionsIsSentOnce() {
        Recorded sink = new Recorded();
        FoxgloveScene scene = new FoxgloveScene(sink);
        ConnectionInfo a = connection(1, 6665), b = connection(2, 6665);
        Laser.Scan s = new Laser.Scan(-1, 1, 1, 8, 3, FloatArray.of(1, 2, 3), 0, ByteArray.EMPTY, 0);
        scene.accept(fromServer(a, T0, Laser.CODE, 0, 1, 1, 4.2, s));
        scene.accept(fromServer(b, T0 + 10, Laser.CODE, 0, 1, 1, 4.2, s));
        scene.accept(fromServer(b, T0 + 20, Laser.CODE, 0, 1, 1, 4.3, s));
        assertEquals(2, sink.of(FoxgloveSchemas.LASER_SCAN).size());
        assertEquals(List.of("robot6665"), scene.robots());
    }

    @Test
    void diagnosticsAndEventsAreLogs() {
        Recorded sink = new Recorded();
        FoxgloveScene scene = new FoxgloveScene(sink);
        ConnectionInfo c = connection(3, 6665);
        scene.event(T0, "connection 3", "connection 3 opened");
        scene.accept(new StreamMessage(SpyStreams.diagnosticKey(c, Direction.SERVER_TO_CLIENT), T0 + 5,
                new SpyDiagnostic(c, Direction.SERVER_TO_CLIENT, 1234, "payload does not fit")));
        List<JsonObject> logs = sink.of(FoxgloveSchemas.LOG);
        assertEquals(2, logs.size());
        assertEquals(FoxgloveNames.EVENTS_TOPIC, sink.topics.get(0));
        assertEquals(FoxgloveNames.DIAGNOSTICS_TOPIC, sink.topics.get(1));
        assertEquals(3, logs.get(1).get("level").getAsInt());
        assertTrue(logs.get(1).get("message").getAsString().contains("offset 1234: payload does not fit"));
        assertEquals(1_795_315_969L, logs.get(1).getAsJsonObject("timestamp").get("sec").getAsLong());
        assertEquals(5, logs.get(1).getAsJsonObject("timestamp").get("nsec").getAsLong());
    }

    /**
     * Every frame a message is in reaches the world through transforms sent no later than the
     * message, and the sink saw messages in time order.
     */
    static void assertFramesChainToWorld(Recorded sink) {
        Map<String, String> parent = new HashMap<>();
        for (int i = 0; i < sink.messages.size(); i++) {
            if (i > 0) {
                assertTrue(sink.times.get(i) >= sink.times.get(i - 1), "out of time order at message " + i);
            }
            JsonObject m = sink.messages.get(i);
            String schema = sink.channels.get(sink.topics.get(i)).schemaName();
            List<String> frames = new ArrayList<>();
            switch (schema) {
                case FoxgloveSchemas.FRAME_TRANSFORM -> parent.put(m.get("child_frame_id").getAsString(),
                        m.get("parent_frame_id").getAsString());
                case FoxgloveSchemas.SCENE_UPDATE -> m.getAsJsonArray("entities")
                        .forEach(e -> frames.add(e.getAsJsonObject().get("frame_id").getAsString()));
                case FoxgloveSchemas.LOG -> {
                }
                default -> frames.add(m.get("frame_id").getAsString());
            }
            for (String f : frames) {
                String at = f;
                for (int hops = 0; !at.equals(FoxgloveNames.WORLD); hops++) {
                    assertTrue(hops < 10, "a cycle above " + f);
                    String up = parent.get(at);
                    assertNotNull(up, "frame " + at + " (of a " + schema + " on " + sink.topics.get(i)
                            + ") has no transform towards the world yet");
                    at = up;
                }
            }
        }
    }
}
