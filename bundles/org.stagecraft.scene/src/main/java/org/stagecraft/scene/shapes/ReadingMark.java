package org.stagecraft.scene.shapes;

import java.util.List;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.scene.BreakReading;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RangerConfig;
import org.stagecraft.scene.WorldModel;

/**
 * Where a view marks the reading a robot data breakpoint stopped on: a ring around the sensor, and for
 * range sensors each deciding beam from the sensor to its return (the nearest laser return of
 * {@code min(ranges) < 0.8}), with a point where it ended; when the whole reading decided (or nothing more
 * is known), a point at every return. Drawn with the robot's current pose: while the breakpoint holds the
 * robot is held and the world frozen, so that is where it stood when it read.
 */
public final class ReadingMark {
    /** The ring's radius and segments, in pixels: a size that reads at any zoom. */
    public static final double RING_PIXELS = 12;
    private static final int RING_SEGMENTS = 24;

    private ReadingMark() {
    }

    /**
     * @param lines  receives line segments (2 vertices each): the ring and the deciding beams
     * @param points receives the returns marked
     */
    public static void build(BreakReading reading, WorldModel world, double metresPerPixel, FloatList lines, FloatList points) {
        DeviceAddress dev = reading.device();
        Pose2 sensor = world.devicePose(dev);
        ring(sensor.x(), sensor.y(), RING_PIXELS * metresPerPixel, lines);
        MessageBody b = reading.body();
        if (b instanceof Laser.Scan scan) {
            BreakReading.Elements ranges = reading.elements("ranges");
            BreakReading.Elements intensity = reading.elements("intensity");
            for (int i = 0; i < scan.ranges().size(); i++) {
                if (ranges.marks(i) || intensity.marks(i)) {
                    boolean single = ranges.indexes().contains(i) || intensity.indexes().contains(i);
                    beam(sensor, scan.angle(i), scan.ranges().get(i), single, lines, points);
                }
            }
        } else if (b instanceof Ranger.Values v && v.name().equals("ranges")) {
            BreakReading.Elements marked = reading.elements("ranges");
            List<Pose2> elements = world.mount(dev).elements();
            RangerConfig config = world.rangerConfig(dev);
            int n = v.values().size();
            boolean perElement = elements.size() == n && n > 1;
            for (int i = 0; i < n; i++) {
                if (marked.marks(i)) {
                    Pose2 from = perElement ? sensor.compose(elements.get(i)) : sensor;
                    beam(from, perElement ? 0 : config.bearing(i, n), v.values().get(i), !marked.whole(), lines, points);
                }
            }
        } else if (b instanceof Sonar.Ranges r) {
            BreakReading.Elements marked = reading.elements("ranges");
            List<Pose2> elements = world.mount(dev).elements();
            for (int i = 0; i < r.ranges().size() && i < elements.size(); i++) {
                if (marked.marks(i)) {
                    beam(sensor.compose(elements.get(i)), 0, r.ranges().get(i), !marked.whole(), lines, points);
                }
            }
        } else if (b instanceof Bumper.State s && world.geometry(dev) instanceof Bumper.Geom geom) {
            BreakReading.Elements marked = reading.elements("bumpers");
            Pose2 robot = world.robot(dev.robot()).pose();
            for (int i = 0; i < s.bumpers().size() && i < geom.bumperDef().size(); i++) {
                if (marked.marks(i) && (!marked.whole() || s.bumpers().unsigned(i) != 0)) {
                    Pose2 at = robot.compose(Pose2.of(geom.bumperDef().get(i).pose()));
                    points.add(at.x(), at.y());
                }
            }
        }
    }

    private static void beam(Pose2 from, double bearing, double range, boolean withLine, FloatList lines, FloatList points) {
        if (!Double.isFinite(range)) {
            return;
        }
        double x = SensorShapes.hitX(from, bearing, range), y = SensorShapes.hitY(from, bearing, range);
        if (withLine) {
            lines.add(from.x(), from.y());
            lines.add(x, y);
        }
        points.add(x, y);
    }

    private static void ring(double cx, double cy, double radius, FloatList lines) {
        for (int k = 0; k < RING_SEGMENTS; k++) {
            double a0 = 2 * Math.PI * k / RING_SEGMENTS, a1 = 2 * Math.PI * (k + 1) / RING_SEGMENTS;
            lines.add(cx + radius * Math.cos(a0), cy + radius * Math.sin(a0));
            lines.add(cx + radius * Math.cos(a1), cy + radius * Math.sin(a1));
        }
    }
}
