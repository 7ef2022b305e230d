package org.stagecraft.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.stagecraft.scene.shapes.FloatList;
import org.stagecraft.scene.shapes.GridShape;
import org.stagecraft.scene.shapes.SensorShapes;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/** Geometry, camera mapping, layers and the persistence format, without GL. */
class SceneModelTest {
    private static final double EPS = 1e-9;

    @Test
    void poseCompositionPutsAMountedSensorInTheWorld() {
        Pose2 robot = new Pose2(2, 1, Math.PI / 2);
        Pose2 sensor = robot.compose(new Pose2(0.2, 0, 0)); // 20 cm ahead of a robot facing +y
        assertEquals(2, sensor.x(), EPS);
        assertEquals(1.2, sensor.y(), EPS);
        assertEquals(Math.PI / 2, sensor.a(), EPS);
        // a hit 1 m straight ahead of that sensor, and one 1 m to its left
        assertEquals(2, SensorShapes.hitX(sensor, 0, 1), EPS);
        assertEquals(2.2, SensorShapes.hitY(sensor, 0, 1), EPS);
        assertEquals(1, SensorShapes.hitX(sensor, Math.PI / 2, 1), EPS);
        assertEquals(1.2, SensorShapes.hitY(sensor, Math.PI / 2, 1), EPS);
    }

    @Test
    void robotIdIsThePlayerSideOfTheStream() {
        StreamKey data = new StreamKey("127.0.0.1:6665", "127.0.0.1:40001", 1, 4, 0, 1);
        StreamKey cmd = new StreamKey("127.0.0.1:40001", "127.0.0.1:6665", 2, 4, 0, 1);
        assertEquals(new RobotId("127.0.0.1:6665"), RobotId.of(data));
        assertEquals(new RobotId("127.0.0.1:6665"), RobotId.of(cmd));
    }

    @Test
    void cameraMapsWorldToPixelsAndBack() {
        Camera c = new Camera(1, 2, 0.01);
        c.viewport(200, 100);
        assertEquals(0, c.left(), EPS);
        assertEquals(2, c.right(), EPS);
        assertEquals(1.5, c.bottom(), EPS);
        assertEquals(2.5, c.top(), EPS);
        // the world point at the centre of pixel (10, 20)
        double x = c.windowToWorldX(10.5), y = c.windowToWorldY(20.5);
        assertEquals(10, c.pixelColumn(x));
        assertEquals(20, c.pixelRow(y));
        assertEquals(0.105, x, EPS);
    }

    @Test
    void zoomKeepsThePointUnderTheMouseAndPanMovesWithTheDrag() {
        Camera c = new Camera(0, 0, 0.02);
        c.viewport(400, 300);
        double wx = 300.5, wy = 50.5;
        double x = c.windowToWorldX(wx), y = c.windowToWorldY(wy);
        c.zoomAt(wx, wy, 2);
        assertEquals(0.01, c.metresPerPixel(), EPS);
        assertEquals(x, c.windowToWorldX(wx), 1e-9);
        assertEquals(y, c.windowToWorldY(wy), 1e-9);

        c.follow(new RobotId("a"));
        c.pan(10, -20); // drag right and up: the world moves with the mouse
        assertNull(c.followed(), "a drag stops following");
        assertEquals(x - 0.1, c.windowToWorldX(wx), 1e-9);
        assertEquals(y - 0.2, c.windowToWorldY(wy), 1e-9);
    }

    @Test
    void cameraFollowsARobotOnceItsPoseIsKnown() {
        WorldModel w = new WorldModel();
        Camera c = new Camera(5, 5, 0.02);
        c.follow(new RobotId("127.0.0.1:6665"));
        c.track(w);
        assertEquals(5, c.centreX(), EPS, "no pose yet: the camera stays");
        w.accept(new StreamMessage(new StreamKey("127.0.0.1:6665", "c:1", 1, 4, 0, 1), 0,
                new org.stagecraft.player.msg.Position2d.State(new org.stagecraft.player.msg.Geometry.Pose2d(-3, 4, 0),
                        new org.stagecraft.player.msg.Geometry.Pose2d(0, 0, 0), 0)));
        c.track(w);
        assertEquals(-3, c.centreX(), EPS);
        assertEquals(4, c.centreY(), EPS);
    }

    @Test
    void cameraAttributesRoundTrip() {
        Camera c = new Camera(1.25, -7.5, 0.0333);
        c.follow(new RobotId("127.0.0.1:6666"));
        Camera d = new Camera();
        d.fromAttributes(c.toAttributes());
        assertEquals(1.25, d.centreX(), EPS);
        assertEquals(-7.5, d.centreY(), EPS);
        assertEquals(0.0333, d.metresPerPixel(), EPS);
        assertEquals(new RobotId("127.0.0.1:6666"), d.followed());
        d.fromAttributes(Map.of("metresPerPixel", "banana"));
        assertEquals(0.0333, d.metresPerPixel(), EPS, "a malformed value keeps the current one");
    }

    @Test
    void layersRoundTripThroughTheirAttributesAndKeepDrawOrder() {
        List<LayerSpec> defaults = DefaultLayers.create();
        LayerStack stack = new LayerStack(defaults);
        stack.put(stack.get("laser").colour(0x123456, 0.5).order(-1).visible(false));
        assertEquals("laser", stack.inDrawOrder().get(0).id(), "order -1 draws first");

        ViewSetup saved = new ViewSetup(stack.inDrawOrder(), Map.of("centreX", "3.0"));
        List<String> problems = new ArrayList<>();
        ViewSetup read = ViewSetup.read(saved.layerAttributes(), saved.camera(), problems::add);
        assertEquals(saved, read);
        assertTrue(problems.isEmpty(), problems.toString());
        LayerSpec laser = read.layers().get(0);
        assertEquals(0x123456, laser.rgb());
        assertEquals(0.5, laser.alpha(), EPS);
        assertFalse(laser.visible());
        assertEquals(StreamPattern.parse("type=1 dev=6 subtype=1"), laser.pattern());
    }

    @Test
    void aMalformedLayerIsSkippedAndReported() {
        Map<String, String> bad = new HashMap<>(DefaultLayers.create().get(0).toAttributes());
        bad.put("colour", "red");
        Map<String, String> good = DefaultLayers.create().get(1).toAttributes();
        List<String> problems = new ArrayList<>();
        ViewSetup read = ViewSetup.read(List.of(bad, good), Map.of(), problems::add);
        assertEquals(1, read.layers().size());
        assertEquals(1, problems.size());
        assertTrue(problems.get(0).contains("colour 'red'"), problems.get(0));
        assertThrows(IllegalArgumentException.class, () -> LayerSpec.fromAttributes(Map.of("id", "x")));
    }

    @Test
    void sonarConeIsInsideTheTrueSectorAndCoversItsAxis() {
        Pose2 t = new Pose2(1, 1, Math.PI / 4);
        FloatList tris = new FloatList();
        SensorShapes.cone(t, 2, Math.toRadians(15), 8, tris);
        assertEquals(8 * 3, tris.vertices());
        for (int v = 0; v < tris.vertices(); v++) {
            assertTrue(SensorShapes.inCone(t, 2 + 1e-6, Math.toRadians(15) + 1e-6, tris.get(2 * v), tris.get(2 * v + 1)));
        }
        assertTrue(SensorShapes.inCone(t, 2, Math.toRadians(15), SensorShapes.hitX(t, 0, 1.9), SensorShapes.hitY(t, 0, 1.9)));
        assertFalse(SensorShapes.inCone(t, 2, Math.toRadians(15), SensorShapes.hitX(t, 0.2, 1), SensorShapes.hitY(t, 0.2, 1)));
        assertFalse(SensorShapes.inCone(t, 2, Math.toRadians(15), SensorShapes.hitX(t, 0, 2.1), SensorShapes.hitY(t, 0, 2.1)));
    }

    @Test
    void scanHitsLeaveOutBeamsAtMaxRange() {
        FloatList fan = new FloatList(), hits = new FloatList(), outline = new FloatList();
        SensorShapes.scan(Pose2.ORIGIN, new double[] { -0.1, 0, 0.1 }, new double[] { 1, 8, 2 }, 3, 8, fan, hits, outline);
        assertEquals(2 * 3, fan.vertices());
        assertEquals(2, hits.vertices(), "the 8 m beam hit nothing");
        assertEquals(2 * 2, outline.vertices());
        assertEquals(2 * Math.cos(0.1), hits.get(2), 1e-6);
    }

    @Test
    void zoomedOutScansDropOnlyBeamsWithinTheSpacingOfAKeptOne() {
        int n = 181;
        double[] b = new double[n], r = new double[n];
        for (int i = 0; i < n; i++) {
            b[i] = Math.toRadians(i - 90);
            r[i] = 1 + (i % 7) * 0.01;
        }
        FloatList all = new FloatList(), kept = new FloatList(), fan = new FloatList();
        SensorShapes.scan(Pose2.ORIGIN, b, r, n, 8, 0, null, all, null);
        SensorShapes.scan(Pose2.ORIGIN, b, r, n, 8, 0.05, fan, kept, null);
        assertEquals(n, all.vertices());
        assertTrue(kept.vertices() < n / 2, "kept " + kept.vertices());
        assertEquals(all.get(0), kept.get(0));
        assertEquals(all.get(2 * n - 1), kept.get(kept.size() - 1), "the last beam is kept");
        assertEquals(3 * (kept.vertices() - 1), fan.vertices());
        for (int i = 0; i < n; i++) {
            double x = all.get(2 * i), y = all.get(2 * i + 1), nearest = Double.MAX_VALUE;
            for (int k = 0; k < kept.vertices(); k++) {
                nearest = Math.min(nearest, Math.max(Math.abs(kept.get(2 * k) - x), Math.abs(kept.get(2 * k + 1) - y)));
            }
            assertTrue(nearest < 0.05 + 1e-6, "beam " + i + " is " + nearest + " m from a kept one");
        }
        assertEquals(6, SensorShapes.coneSegments(2, Math.toRadians(15), 0.01, 6));
        assertEquals(1, SensorShapes.coneSegments(0.2, Math.toRadians(15), 0.2, 6));
    }

    @Test
    void gridSpacingKeepsLinesApart() {
        Camera c = new Camera(0, 0, 0.02);
        c.viewport(800, 600);
        assertEquals(0.5, GridShape.spacing(c), EPS); // 0.1 m would be 5 px
        c.setMetresPerPixel(0.2);
        assertEquals(5, GridShape.spacing(c), EPS);
        FloatList minor = new FloatList(), major = new FloatList();
        GridShape.lines(c, 5, minor, major);
        assertTrue(major.vertices() > 0 && minor.vertices() > 0);
    }
}
