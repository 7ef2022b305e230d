package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.scene.BreakReading;
import org.stagecraft.scene.Camera;
import org.stagecraft.scene.DefaultLayers;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RobotId;
import org.stagecraft.scene.shapes.ReadingMark;
import org.stagecraft.scene.shapes.SensorShapes;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.views.FramePixels;
import org.stagecraft.views.renderers.LaserRenderer;
import org.stagecraft.views.renderers.SonarRenderer;

/**
 * Frames of recorded data drawn by the real renderers in a JOGL canvas (Xvfb + Mesa), read back, and
 * checked pixel by pixel against where the geometry says things must be: each laser hit on its computed
 * pixel, each sonar cone covering its computed sector with the configured blend, a hidden layer drawing
 * nothing, and superimposed layers blending as configured.
 */
class PixelTest {
    static final int W = 400, H = 300, TOL = 3;
    static final double MPP = 0.02; // 8 m x 6 m
    static final int LASER_RGB = 0x1A4DFF, SONAR_RGB = 0x19E633;

    static GlHarness gl;
    RecordedScene rec;
    Laser.Scan scan;
    Pose2 laserPose;

    @BeforeAll
    static void shell() {
        gl = new GlHarness(W, H);
    }

    @AfterAll
    static void close() {
        gl.close();
    }

    @BeforeEach
    void scene() throws Exception {
        rec = new RecordedScene(150); // 15 s into the session: the robot has driven into the world
        rec.layer(new LayerSpec("sonar", DefaultLayers.SONAR, "Sonar", StreamPattern.parse("type=1 dev=62 subtype=1"),
                true, SONAR_RGB, 0.3, 10), new SonarRenderer(), rec.sonar);
        rec.layer(new LayerSpec("laser", DefaultLayers.LASER, "Laser", StreamPattern.parse("type=1 dev=6 subtype=1"),
                true, LASER_RGB, 0.35, 20), new LaserRenderer(), rec.laser);
        RobotId robot = new RobotId(RecordedScene.PLAYER);
        Pose2 p = rec.world.robot(robot).pose();
        rec.camera.centreOn(p.x(), p.y());
        rec.camera.setMetresPerPixel(MPP);
        rec.camera.viewport(W, H);
        scan = (Laser.Scan) Payloads.body(rec.laser);
        laserPose = rec.world.devicePose(new DeviceAddress(robot, 6, 0));
    }

    private FramePixels baseline() {
        rec.hideAll();
        return gl.frame(rec.scene);
    }

    @Test
    void laserHitsLandOnTheirComputedPixels() {
        FramePixels base = baseline();
        rec.show("laser", true);
        FramePixels f = gl.frame(rec.scene);
        Camera c = rec.camera;
        List<double[]> hits = new ArrayList<>();
        int checked = 0;
        for (int i = 0; i < scan.ranges().size(); i++) {
            double r = scan.ranges().get(i);
            if (r >= scan.maxRange()) {
                continue;
            }
            double x = SensorShapes.hitX(laserPose, scan.angle(i), r), y = SensorShapes.hitY(laserPose, scan.angle(i), r);
            hits.add(new double[] { c.worldToWindowX(x), c.worldToWindowY(y) });
            int col = c.pixelColumn(x), row = c.pixelRow(y);
            if (col < 3 || row < 3 || col >= W - 3 || row >= H - 3) {
                continue;
            }
            assertColour(LASER_RGB, f.rgb(col, row), 2, "hit of beam " + i + " (r=" + r + " m) at pixel " + col + "," + row);
            checked++;
        }
        assertTrue(checked >= 30, "hits inside the frame: " + checked);

        // 8 px beyond each hit (far from every other hit) there is no hit colour
        int beyond = 0;
        for (int i = 0; i < scan.ranges().size(); i++) {
            double r = scan.ranges().get(i) + 8 * MPP;
            if (scan.ranges().get(i) >= scan.maxRange()) {
                continue;
            }
            double wx = c.worldToWindowX(SensorShapes.hitX(laserPose, scan.angle(i), r));
            double wy = c.worldToWindowY(SensorShapes.hitY(laserPose, scan.angle(i), r));
            if (wx < 3 || wy < 3 || wx >= W - 3 || wy >= H - 3 || hits.stream().anyMatch(h -> Math.hypot(h[0] - wx, h[1] - wy) < 6)) {
                continue;
            }
            int got = f.rgb((int) wx, (int) wy);
            assertTrue(!FramePixels.close(got, LASER_RGB, 12), "beyond hit " + i + ": " + hex(got));
            beyond++;
        }
        assertTrue(beyond >= 10, "points beyond hits checked: " + beyond);
        assertTrue(f.differingPixels(base) > 1000, "the laser layer drew");
    }

    /**
     * Issue 27: while a robot data breakpoint holds, the view marks the reading it stopped on: the beam that
     * decided {@code min(ranges) < ...} from the laser to its return (yellow on a black edge), and a ring around the laser;
     * the other beams are not marked, and without a mark nothing has its colour.
     */
    @Test
    void theBreakpointsReadingIsMarkedAlongItsDecidingBeam() {
        baseline();
        int n = scan.ranges().size(), k = 0;
        for (int i = 1; i < n; i++) {
            k = scan.ranges().get(i) < scan.ranges().get(k) ? i : k;
        }
        int opposite = (k + n / 2) % n;
        RobotId robot = new RobotId(RecordedScene.PLAYER);
        rec.scene.mark(new BreakReading(new DeviceAddress(robot, Laser.CODE, 0), scan, List.of("ranges[" + k + "]")));
        int mark = 0xFFD400; // RobotScene.MARK
        Camera c = rec.camera;
        try {
            FramePixels f = gl.frame(rec.scene);
            int along = 0;
            for (int step = 3; step <= 10; step++) { // from 30% of the beam to its return
                double r = scan.ranges().get(k) * step / 10;
                double x = SensorShapes.hitX(laserPose, scan.angle(k), r), y = SensorShapes.hitY(laserPose, scan.angle(k), r);
                int col = c.pixelColumn(x), row = c.pixelRow(y);
                if (f.contains(col, row)) {
                    assertColour(mark, f.rgb(col, row), TOL, "beam " + k + " at " + step * 10 + "% (pixel " + col + "," + row + ")");
                    along++;
                }
            }
            assertTrue(along >= 4, "pixels checked along the deciding beam: " + along);
            double ring = ReadingMark.RING_PIXELS * MPP;
            int ringCol = c.pixelColumn(laserPose.x() + ring), ringRow = c.pixelRow(laserPose.y());
            assertColour(mark, f.rgb(ringCol, ringRow), TOL, "the ring around the laser at " + ringCol + "," + ringRow);
            double far = scan.ranges().get(opposite) * 0.7;
            if (far > 3 * ring) { // clear of the ring
                int col = c.pixelColumn(SensorShapes.hitX(laserPose, scan.angle(opposite), far));
                int row = c.pixelRow(SensorShapes.hitY(laserPose, scan.angle(opposite), far));
                assertTrue(!f.contains(col, row) || !FramePixels.close(mark, f.rgb(col, row), 40),
                        "beam " + opposite + " (not deciding) is not marked");
            }
            assertTrue(f.count(mark, TOL) < 2000, "a mark, not a painted frame: " + f.count(mark, TOL) + " pixels of the mark colour");
            rec.scene.mark(null);
            assertEquals(0, gl.frame(rec.scene).count(mark, TOL), "no mark, no mark colour");
        } finally {
            rec.scene.mark(null);
        }
    }

    @Test
    void sonarConesCoverTheirComputedArea() {
        FramePixels base = baseline();
        rec.show("sonar", true);
        FramePixels f = gl.frame(rec.scene);
        int[] counts = checkCones(f, base, 0.3);
        assertTrue(counts[0] >= 100, "pixels checked inside cones: " + counts[0]);
        assertTrue(counts[1] >= 100, "pixels checked outside cones: " + counts[1]);
    }

    @Test
    void aHiddenLayerDrawsNothing() {
        FramePixels base = baseline();
        rec.show("sonar", true);
        rec.show("laser", true);
        FramePixels both = gl.frame(rec.scene);
        assertTrue(both.differingPixels(base) > 1000);
        rec.show("laser", false);
        FramePixels sonarOnly = gl.frame(rec.scene);
        rec.show("sonar", false);
        rec.show("laser", true);
        FramePixels laserOnly = gl.frame(rec.scene);
        rec.show("laser", false);
        assertEquals(0, gl.frame(rec.scene).differingPixels(base), "all layers hidden: nothing but the grid");
        assertTrue(sonarOnly.differingPixels(both) > 500, "hiding the laser removed it");
        assertTrue(laserOnly.differingPixels(both) > 500, "hiding the sonar removed it");
        // the sonar-only frame is exactly the sonar layer: its cones and nothing of the laser
        assertEquals(0, sonarOnly.count(LASER_RGB, 2), "no laser hit pixels while the laser is hidden");
        assertTrue(laserOnly.count(LASER_RGB, 2) > 30);
    }

    @Test
    void alphaBlendsAsConfigured() {
        FramePixels base = baseline();
        rec.scene.updateLayer(rec.spec("sonar").colour(SONAR_RGB, 0.75).visible(true));
        int[] counts = checkCones(gl.frame(rec.scene), base, 0.75);
        assertTrue(counts[0] >= 100, "pixels checked inside cones: " + counts[0]);

        // laser fan (0.35) over sonar cones (0.3): where both cover a pixel it is blended twice, in draw order
        rec.scene.updateLayer(rec.spec("sonar").colour(SONAR_RGB, 0.3));
        rec.show("laser", true);
        FramePixels f = gl.frame(rec.scene);
        Camera c = rec.camera;
        int single = 0, dbl = 0;
        for (int i = 0; i + 1 < scan.ranges().size(); i++) {
            double r = 0.4 * Math.min(scan.ranges().get(i), scan.ranges().get(i + 1));
            double a = (scan.angle(i) + scan.angle(i + 1)) / 2;
            double x = SensorShapes.hitX(laserPose, a, r), y = SensorShapes.hitY(laserPose, a, r);
            int col = c.pixelColumn(x), row = c.pixelRow(y);
            if (r < 12 * MPP || col < 3 || row < 3 || col >= W - 3 || row >= H - 3) {
                continue;
            }
            double px = c.windowToWorldX(col + 0.5), py = c.windowToWorldY(row + 0.5);
            int inside = conesContaining(px, py);
            if (inside < 0 || inside > 1) {
                continue; // near a cone edge, or two cones: not a clean probe
            }
            int below = inside == 1 ? FramePixels.blend(SONAR_RGB, 0.3, base.rgb(col, row)) : base.rgb(col, row);
            assertColour(FramePixels.blend(LASER_RGB, 0.35, below), f.rgb(col, row), TOL,
                    "fan of beam " + i + (inside == 1 ? " over a sonar cone" : " over the background"));
            if (inside == 1) {
                dbl++;
            } else {
                single++;
            }
        }
        assertTrue(dbl >= 5 && single >= 5, "probes over cones " + dbl + ", over background " + single);
    }

    @Test
    void theRobotIsDrawnAtItsPoseWithItsFootprintAndHeading() {
        rec.layer(new LayerSpec("robots", DefaultLayers.POSITION2D, "Robots", StreamPattern.parse("type=1 dev=4 subtype=1"),
                true, 0xE61A1A, 1.0, 30), new org.stagecraft.views.renderers.Position2dRenderer(),
                new org.stagecraft.streams.StreamMessage(new org.stagecraft.streams.StreamKey(RecordedScene.PLAYER,
                        "127.0.0.1:40001", 1, 4, 0, 1), 0, new Object()));
        rec.hideAll();
        rec.show("robots", true);
        rec.camera.setMetresPerPixel(0.004); // the 44 x 38 cm Pioneer is 110 x 95 px
        FramePixels f = gl.frame(rec.scene);
        RobotId robot = new RobotId(RecordedScene.PLAYER);
        Pose2 body = rec.world.robot(robot).pose().compose(rec.world.robot(robot).body().pose());
        int heading = 0x670B0B; // #E61A1A at shade 0.45
        // in the body frame: the heading marker points forward (+x), the footprint is 0.44 x 0.38 m
        assertColour(heading, probe(f, body, 0.12, 0), 3, "ahead of the centre: heading marker");
        assertColour(0xE61A1A, probe(f, body, -0.15, 0), 3, "behind the centre: footprint");
        assertColour(0xE61A1A, probe(f, body, 0.18, 0.15), 3, "front left corner: footprint");
        assertTrue(!FramePixels.close(0xE61A1A, probe(f, body, 0.26, 0), 40), "beyond the front: no footprint");
        assertTrue(!FramePixels.close(0xE61A1A, probe(f, body, 0, 0.23), 40), "beyond the side: no footprint");
    }

    private int probe(FramePixels f, Pose2 frame, double x, double y) {
        return f.rgb(rec.camera.pixelColumn(frame.toParentX(x, y)), rec.camera.pixelRow(frame.toParentY(x, y)));
    }

    /** Checks every 3rd pixel: inside exactly one cone it is the blend, outside all it is the background. */
    private int[] checkCones(FramePixels f, FramePixels base, double alpha) {
        Camera c = rec.camera;
        int in = 0, out = 0;
        for (int row = 3; row < H - 3; row += 3) {
            for (int col = 3; col < W - 3; col += 3) {
                double x = c.windowToWorldX(col + 0.5), y = c.windowToWorldY(row + 0.5);
                int n = conesContaining(x, y);
                if (n == 1) {
                    assertColour(FramePixels.blend(SONAR_RGB, alpha, base.rgb(col, row)), f.rgb(col, row), TOL,
                            "inside one cone at " + col + "," + row);
                    in++;
                } else if (n == 0) {
                    assertColour(base.rgb(col, row), f.rgb(col, row), 1, "outside every cone at " + col + "," + row);
                    out++;
                }
            }
        }
        return new int[] { in, out };
    }

    /**
     * How many sonar cones contain the point by at least 3 pixels' margin; -1 if it is within 3 pixels of
     * a cone's edge (where rasterisation may go either way).
     */
    private int conesContaining(double x, double y) {
        DeviceAddress dev = new DeviceAddress(new RobotId(RecordedScene.PLAYER), 62, 0);
        Ranger.Values v = (Ranger.Values) Payloads.body(rec.sonar);
        double margin = 3 * MPP, half = SonarRenderer.DEFAULT_APERTURE / 2;
        int inside = 0;
        for (int i = 0; i < v.values().size(); i++) {
            Pose2 t = SonarRenderer.transducer(rec.world, dev, i);
            double r = v.values().get(i);
            double dx = x - t.x(), dy = y - t.y(), d = Math.hypot(dx, dy);
            double off = Math.abs(Math.IEEEremainder(Math.atan2(dy, dx) - t.a(), 2 * Math.PI));
            // signed distance to the sector's boundary: > 0 inside, < 0 outside
            double edge = off <= half ? Math.min(r - d, d * Math.sin(half - off))
                    : -Math.max(d - r, d * Math.sin(Math.min(off - half, Math.PI / 2)));
            if (d < margin || Math.abs(edge) < margin) {
                return -1;
            }
            if (edge > 0) {
                inside++;
            }
        }
        return inside;
    }

    private static void assertColour(int expected, int actual, int tol, String where) {
        assertTrue(FramePixels.close(expected, actual, tol), where + ": expected " + hex(expected) + " got " + hex(actual));
    }

    private static String hex(int rgb) {
        return String.format("#%06X", rgb);
    }
}
