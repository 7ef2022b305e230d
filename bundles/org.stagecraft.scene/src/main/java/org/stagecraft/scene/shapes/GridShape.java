package org.stagecraft.scene.shapes;

import org.stagecraft.scene.Camera;

/** The metre grid behind everything: lines every 1, 5, 10, 50... m, whichever keeps them >= 8 px apart. */
public final class GridShape {
    private GridShape() {
    }

    /** Grid spacing in metres for the camera's zoom. */
    public static double spacing(Camera c) {
        double[] steps = { 0.1, 0.5, 1, 5, 10, 50, 100, 500, 1000 };
        for (double s : steps) {
            if (s / c.metresPerPixel() >= 8) {
                return s;
            }
        }
        return steps[steps.length - 1];
    }

    /** Lines covering the view at {@code spacing}; every fifth (multiples of 5 x spacing) into {@code major}. */
    public static void lines(Camera c, double spacing, FloatList minor, FloatList major) {
        double l = c.left(), r = c.right(), b = c.bottom(), t = c.top();
        for (long i = (long) Math.floor(l / spacing); i * spacing <= r; i++) {
            (i % 5 == 0 ? major : minor).add(i * spacing, b);
            (i % 5 == 0 ? major : minor).add(i * spacing, t);
        }
        for (long j = (long) Math.floor(b / spacing); j * spacing <= t; j++) {
            (j % 5 == 0 ? major : minor).add(l, j * spacing);
            (j % 5 == 0 ? major : minor).add(r, j * spacing);
        }
    }
}
