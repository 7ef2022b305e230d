package org.stagecraft.scene.shapes;

import org.stagecraft.scene.Pose2;

/**
 * Range-sensor geometry in world coordinates: where a beam hits, the fan of a scan, the cone of a sonar.
 * The renderers draw exactly these vertices and the pixel tests predict pixels from the same functions.
 */
public final class SensorShapes {
    private SensorShapes() {
    }

    /** x of the point at {@code range} along {@code bearing} of a sensor at {@code sensor} (world pose). */
    public static double hitX(Pose2 sensor, double bearing, double range) {
        return sensor.x() + range * Math.cos(sensor.a() + bearing);
    }

    public static double hitY(Pose2 sensor, double bearing, double range) {
        return sensor.y() + range * Math.sin(sensor.a() + bearing);
    }

    /**
     * A scan: triangles of the swept area (sensor to consecutive hits), the hit points (beams shorter than
     * {@code maxRange}: a beam at max range hit nothing), and the outline as line segments.
     *
     * @param fan      receives triangles (3 vertices each), or null
     * @param hits     receives points, or null
     * @param outline  receives line segments (2 vertices each), or null
     */
    public static void scan(Pose2 sensor, double[] bearings, double[] ranges, int count, double maxRange, FloatList fan,
            FloatList hits, FloatList outline) {
        scan(sensor, bearings, ranges, count, maxRange, 0, fan, hits, outline);
    }

    /**
     * As {@link #scan(Pose2, double[], double[], int, double, FloatList, FloatList, FloatList)}, leaving out
     * beams whose end lies within {@code minSpacing} metres of the last beam end kept (the first and last
     * beam are always kept). With {@code minSpacing} below a pixel the picture is the same, with far fewer
     * (and no sub-pixel) triangles when zoomed out: a software rasteriser's cost is mostly per triangle.
     */
    public static void scan(Pose2 sensor, double[] bearings, double[] ranges, int count, double maxRange,
            double minSpacing, FloatList fan, FloatList hits, FloatList outline) {
        double px = 0, py = 0;
        boolean first = true;
        for (int i = 0; i < count; i++) {
            double r = Math.max(0, Math.min(ranges[i], maxRange > 0 ? maxRange : ranges[i]));
            if (!Double.isFinite(r)) {
                continue;
            }
            double x = hitX(sensor, bearings[i], r), y = hitY(sensor, bearings[i], r);
            if (!first && i < count - 1 && minSpacing > 0 && Math.abs(x - px) < minSpacing && Math.abs(y - py) < minSpacing) {
                continue;
            }
            if (!first) {
                if (fan != null) {
                    fan.add(sensor.x(), sensor.y());
                    fan.add(px, py);
                    fan.add(x, y);
                }
                if (outline != null) {
                    outline.add(px, py);
                    outline.add(x, y);
                }
            }
            if (hits != null && (maxRange <= 0 || ranges[i] < maxRange)) {
                hits.add(x, y);
            }
            px = x;
            py = y;
            first = false;
        }
    }

    /** Slices for a sonar cone: about one per 4 pixels of arc, 1 to {@code max}. */
    public static int coneSegments(double range, double aperture, double metresPerPixel, int max) {
        double arcPixels = range * aperture / Math.max(1e-9, metresPerPixel);
        return (int) Math.max(1, Math.min(max, Math.ceil(arcPixels / 4)));
    }

    /**
     * A sonar cone as triangles: apex at the transducer, {@code segments} slices across the aperture.
     * The arc is approximated by chords, so the drawn cone lies inside the true one.
     */
    public static void cone(Pose2 transducer, double range, double aperture, int segments, FloatList triangles) {
        if (!(range > 0) || !Double.isFinite(range)) {
            return;
        }
        double start = -aperture / 2, step = aperture / segments;
        double px = hitX(transducer, start, range), py = hitY(transducer, start, range);
        for (int s = 1; s <= segments; s++) {
            double x = hitX(transducer, start + s * step, range), y = hitY(transducer, start + s * step, range);
            triangles.add(transducer.x(), transducer.y());
            triangles.add(px, py);
            triangles.add(x, y);
            px = x;
            py = y;
        }
    }

    /** Whether world point (x, y) is inside the true (circular-sector) cone. */
    public static boolean inCone(Pose2 transducer, double range, double aperture, double x, double y) {
        double dx = x - transducer.x(), dy = y - transducer.y();
        double d = Math.hypot(dx, dy);
        if (d < 1e-6) {
            return true; // the apex
        }
        double off = Math.IEEEremainder(Math.atan2(dy, dx) - transducer.a(), 2 * Math.PI);
        return d <= range && Math.abs(off) <= aperture / 2;
    }

    /** Adds a filled axis-aligned square of side {@code size} centred on (x, y), as two triangles. */
    public static void square(double x, double y, double size, FloatList triangles) {
        double h = size / 2;
        quad(x - h, y - h, x + h, y - h, x + h, y + h, x - h, y + h, triangles);
    }

    /** Adds the quad (a, b, c, d), counter-clockwise, as two triangles. */
    public static void quad(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy,
            FloatList triangles) {
        triangles.add(ax, ay);
        triangles.add(bx, by);
        triangles.add(cx, cy);
        triangles.add(ax, ay);
        triangles.add(cx, cy);
        triangles.add(dx, dy);
    }
}
