package org.stagecraft.scene;

import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;

/**
 * The Robot View's 2D camera: which world point is at the centre of the view, how many metres one pixel
 * spans, and optionally a robot to follow. It also owns the mapping between world metres and window
 * pixels that both the GL projection and the pixel tests use, so the two cannot disagree.
 *
 * <p>Window coordinates are OpenGL's: x to the right, y <em>up</em>, (0,0) the bottom-left corner of the
 * bottom-left pixel; pixel (i, j) covers [i, i+1) x [j, j+1). Mouse coordinates (y down) are converted with
 * {@link #mouseToWindowY(int)}.
 */
public final class Camera {
    public static final double MIN_METRES_PER_PIXEL = 1e-4, MAX_METRES_PER_PIXEL = 10;

    private double centreX, centreY, metresPerPixel = 0.02;
    private @Nullable RobotId followed;
    private int width = 1, height = 1;

    public Camera() {
    }

    public Camera(double centreX, double centreY, double metresPerPixel) {
        this.centreX = centreX;
        this.centreY = centreY;
        this.metresPerPixel = clamp(metresPerPixel);
    }

    /** Size of the drawing surface in pixels. */
    public void viewport(int width, int height) {
        this.width = Math.max(1, width);
        this.height = Math.max(1, height);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public double centreX() {
        return centreX;
    }

    public double centreY() {
        return centreY;
    }

    public double metresPerPixel() {
        return metresPerPixel;
    }

    public @Nullable RobotId followed() {
        return followed;
    }

    /** Keeps the robot in the centre from now on (null: stop following). */
    public void follow(@Nullable RobotId robot) {
        followed = robot;
    }

    /** Before each frame: centres on the followed robot, if any and if it has a pose. */
    public void track(WorldModel world) {
        if (followed != null) {
            RobotState r = world.robot(followed);
            if (r.poseSeen()) {
                centreX = r.pose().x();
                centreY = r.pose().y();
            }
        }
    }

    public void centreOn(double x, double y) {
        centreX = x;
        centreY = y;
    }

    /** Moves the view by a mouse drag of (dx, dy) pixels (dy down); stops following. */
    public void pan(double dxPixels, double dyPixels) {
        followed = null;
        centreX -= dxPixels * metresPerPixel;
        centreY += dyPixels * metresPerPixel;
    }

    /** Zooms by {@code factor} (> 1 zooms in) keeping the world point under window point (wx, wy) fixed. */
    public void zoomAt(double wx, double wy, double factor) {
        double x = windowToWorldX(wx), y = windowToWorldY(wy);
        metresPerPixel = clamp(metresPerPixel / factor);
        if (followed == null) {
            centreX = x - (wx - width / 2.0) * metresPerPixel;
            centreY = y - (wy - height / 2.0) * metresPerPixel;
        }
    }

    public void setMetresPerPixel(double mpp) {
        metresPerPixel = clamp(mpp);
    }

    // ---- the mapping ------------------------------------------------------------------------------

    public double left() {
        return centreX - width / 2.0 * metresPerPixel;
    }

    public double right() {
        return centreX + width / 2.0 * metresPerPixel;
    }

    public double bottom() {
        return centreY - height / 2.0 * metresPerPixel;
    }

    public double top() {
        return centreY + height / 2.0 * metresPerPixel;
    }

    public double worldToWindowX(double x) {
        return (x - left()) / metresPerPixel;
    }

    public double worldToWindowY(double y) {
        return (y - bottom()) / metresPerPixel;
    }

    public double windowToWorldX(double wx) {
        return left() + wx * metresPerPixel;
    }

    public double windowToWorldY(double wy) {
        return bottom() + wy * metresPerPixel;
    }

    /** Column of the pixel containing world point x. */
    public int pixelColumn(double x) {
        return (int) Math.floor(worldToWindowX(x));
    }

    /** Row (counted from the bottom, as glReadPixels does) of the pixel containing world point y. */
    public int pixelRow(double y) {
        return (int) Math.floor(worldToWindowY(y));
    }

    public double mouseToWindowY(int mouseY) {
        return height - mouseY - 0.5;
    }

    // ---- persistence -------------------------------------------------------------------------------

    /** The camera as string attributes (the Robot View stores them in its memento). */
    public Map<String, String> toAttributes() {
        Map<String, String> a = new LinkedHashMap<>();
        a.put("centreX", Double.toString(centreX));
        a.put("centreY", Double.toString(centreY));
        a.put("metresPerPixel", Double.toString(metresPerPixel));
        if (followed != null) {
            a.put("follow", followed.address());
        }
        return a;
    }

    /** Restores what {@link #toAttributes()} wrote; missing or malformed values keep the current ones. */
    public void fromAttributes(Map<String, String> a) {
        centreX = number(a.get("centreX"), centreX);
        centreY = number(a.get("centreY"), centreY);
        metresPerPixel = clamp(number(a.get("metresPerPixel"), metresPerPixel));
        @Nullable String f = a.get("follow");
        followed = f == null || f.isBlank() ? null : new RobotId(f);
    }

    private static double number(String s, double fallback) {
        if (s == null) {
            return fallback;
        }
        try {
            double v = Double.parseDouble(s);
            return Double.isFinite(v) ? v : fallback;
        } catch (NumberFormatException e) {
            return fallback;
        }
    }

    private static double clamp(double mpp) {
        return Math.max(MIN_METRES_PER_PIXEL, Math.min(MAX_METRES_PER_PIXEL, mpp));
    }
}
