package org.stagecraft.views.renderers;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.shapes.SensorShapes;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.GlBatch;
import org.stagecraft.views.GlBatch.Tint;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.ShapeRenderer;

import com.jogamp.opengl.GL;

/**
 * Laser scans (laser DATA SCAN): the swept area semi-transparent, its outline, and the hits as opaque
 * points (beams at max range hit nothing and get no point); hits with a non-zero intensity are drawn
 * larger and darker.
 */
public class LaserRenderer extends ShapeRenderer {
    private final GlBatch fan = batch(new GlBatch(GL.GL_TRIANGLES, Tint.LAYER));
    private final GlBatch outline = batch(new GlBatch(GL.GL_LINES, new Tint(0.7f, 2f, false)));
    private final GlBatch hits = batch(new GlBatch(GL.GL_POINTS, new Tint(1, 1, true)).size(3));
    private final GlBatch bright = batch(new GlBatch(GL.GL_POINTS, new Tint(0.5f, 1, true)).size(5));
    private double[] bearings = new double[0], ranges = new double[0];

    @Override
    protected boolean zoomDependent() {
        return true;
    }

    @Override
    protected void build(RenderInput in) {
        for (StreamMessage m : in.latest()) {
            MessageBody b = Payloads.body(m);
            if (!(b instanceof Laser.Scan scan)) {
                continue;
            }
            int n = scan.ranges().size();
            if (bearings.length < n) {
                bearings = new double[n];
                ranges = new double[n];
            }
            for (int i = 0; i < n; i++) {
                bearings[i] = scan.angle(i);
                ranges[i] = scan.ranges().get(i);
            }
            Pose2 sensor = in.world().devicePose(DeviceAddress.of(m.key()));
            // beams closer than 3/4 pixel to the previous one add nothing visible (the hit points are 3 px)
            SensorShapes.scan(sensor, bearings, ranges, n, scan.maxRange(), 0.75 * in.camera().metresPerPixel(),
                    fan.vertices(), hits.vertices(), outline.vertices());
            int ni = Math.min(n, scan.intensity().size());
            for (int i = 0; i < ni; i++) {
                if (scan.intensity().unsigned(i) > 0 && ranges[i] < scan.maxRange()) {
                    bright.vertices().add(SensorShapes.hitX(sensor, bearings[i], ranges[i]),
                            SensorShapes.hitY(sensor, bearings[i], ranges[i]));
                }
            }
        }
    }
}
