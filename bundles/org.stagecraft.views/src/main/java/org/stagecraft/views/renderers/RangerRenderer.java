package org.stagecraft.views.renderers;

import java.util.List;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.Mount;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RangerConfig;
import org.stagecraft.scene.shapes.SensorShapes;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.GlBatch;
import org.stagecraft.views.GlBatch.Tint;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.ShapeRenderer;

import com.jogamp.opengl.GL;

/**
 * Any ranger (ranger DATA RANGE) as rays and hit points. A ranger whose geometry lists one element per
 * range (a sonar ring) casts each ray from its element; any other is a fan from the device pose with the
 * bearings of its configuration (GET_CONFIG reply; a 180 degree fan until one is seen).
 */
public class RangerRenderer extends ShapeRenderer {
    private final GlBatch rays = batch(new GlBatch(GL.GL_LINES, Tint.LAYER));
    private final GlBatch hits = batch(new GlBatch(GL.GL_POINTS, new Tint(1, 1, true)).size(3));

    @Override
    protected void build(RenderInput in) {
        for (StreamMessage m : in.latest()) {
            MessageBody b = Payloads.body(m);
            if (!(b instanceof Ranger.Values v) || !"ranges".equals(v.name())) {
                continue;
            }
            DeviceAddress dev = DeviceAddress.of(m.key());
            Pose2 device = in.world().devicePose(dev);
            Mount mount = in.world().mount(dev);
            RangerConfig config = in.world().rangerConfig(dev);
            List<Pose2> elements = mount.elements();
            int n = v.values().size();
            boolean perElement = elements.size() == n && n > 1;
            for (int i = 0; i < n; i++) {
                double r = v.values().get(i);
                Pose2 from = perElement ? device.compose(elements.get(i)) : device;
                double bearing = perElement ? 0 : config.bearing(i, n);
                double x = SensorShapes.hitX(from, bearing, r), y = SensorShapes.hitY(from, bearing, r);
                rays.vertices().add(from.x(), from.y());
                rays.vertices().add(x, y);
                if (!config.seen() || r < config.maxRange()) {
                    hits.vertices().add(x, y);
                }
            }
        }
    }
}
