package org.stagecraft.views.renderers;

import java.util.List;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Sonar;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.Mount;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RangerConfig;
import org.stagecraft.scene.WorldModel;
import org.stagecraft.scene.shapes.SensorShapes;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.GlBatch;
import org.stagecraft.views.GlBatch.Tint;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.ShapeRenderer;

import com.jogamp.opengl.GL;

/**
 * Sonar cones: one per transducer, from its mounting pose (sonar geometry, or the element poses of a
 * sonar-like ranger's geometry) out to the measured range. Rangers that are not sonar-like (one element,
 * e.g. a laser exposed as a ranger) are left to the ranger renderer.
 */
public class SonarRenderer extends ShapeRenderer {
    /** Cone aperture until a ranger configuration says otherwise: Stage's Pioneer sonars (fov 15). */
    public static final double DEFAULT_APERTURE = Math.toRadians(15);
    public static final int SEGMENTS = 6;

    private final GlBatch cones = batch(new GlBatch(GL.GL_TRIANGLES, Tint.LAYER));

    @Override
    protected void build(RenderInput in) {
        for (StreamMessage m : in.latest()) {
            MessageBody b = Payloads.body(m);
            DeviceAddress dev = DeviceAddress.of(m.key());
            if (b instanceof Sonar.Ranges r) {
                double[] ranges = new double[r.ranges().size()];
                for (int i = 0; i < ranges.length; i++) {
                    ranges[i] = r.ranges().get(i);
                }
                cones(in, dev, ranges, DEFAULT_APERTURE);
            } else if (b instanceof Ranger.Values v && "ranges".equals(v.name())) {
                RangerConfig c = in.world().rangerConfig(dev);
                double aperture = c.seen() && c.maxAngle() > c.minAngle() ? c.maxAngle() - c.minAngle() : DEFAULT_APERTURE;
                cones(in, dev, v.values().toArray(), aperture);
            }
        }
    }

    @Override
    protected boolean zoomDependent() {
        return true;
    }

    private void cones(RenderInput in, DeviceAddress dev, double[] ranges, double aperture) {
        WorldModel world = in.world();
        Mount mount = world.mount(dev);
        List<Pose2> elements = mount.elements();
        if (elements.size() != ranges.length || ranges.length < 2) {
            return; // not sonar-like (or no geometry yet): nowhere to put the cones
        }
        Pose2 device = world.devicePose(dev);
        for (int i = 0; i < ranges.length; i++) {
            // fewer slices when a cone is only a few pixels across: same picture, fewer triangles
            int segments = SensorShapes.coneSegments(ranges[i], aperture, in.camera().metresPerPixel(), SEGMENTS);
            SensorShapes.cone(device.compose(elements.get(i)), ranges[i], aperture, segments, cones.vertices());
        }
    }

    /** The world pose of transducer i (for tests and tools). */
    public static Pose2 transducer(WorldModel world, DeviceAddress dev, int i) {
        return world.devicePose(dev).compose(world.mount(dev).elements().get(i));
    }
}
