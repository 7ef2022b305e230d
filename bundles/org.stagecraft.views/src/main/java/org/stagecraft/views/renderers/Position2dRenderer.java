package org.stagecraft.views.renderers;

import java.util.LinkedHashSet;
import java.util.Set;

import org.stagecraft.scene.RobotId;
import org.stagecraft.scene.RobotState;
import org.stagecraft.scene.shapes.RobotShapes;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.GlBatch;
import org.stagecraft.views.GlBatch.Tint;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.ShapeRenderer;

import com.jogamp.opengl.GL;

/**
 * Robots (position2d): the trail, the footprint from the position2d geometry, a heading marker and the
 * velocity (where the robot would be in one second). Draws the robots whose position2d streams match the
 * layer's pattern, at the world model's newest pose.
 */
public class Position2dRenderer extends ShapeRenderer {
    private final GlBatch trail = batch(new GlBatch(GL.GL_LINES, new Tint(0.8f, 0.6f, false)).size(1));
    private final GlBatch body = batch(new GlBatch(GL.GL_TRIANGLES, Tint.LAYER));
    private final GlBatch heading = batch(new GlBatch(GL.GL_TRIANGLES, new Tint(0.45f, 1, true)));
    private final GlBatch velocity = batch(new GlBatch(GL.GL_LINES, new Tint(0.45f, 1, true)).size(2));

    @Override
    protected boolean zoomDependent() {
        return true;
    }

    @Override
    protected void build(RenderInput in) {
        Set<RobotId> robots = new LinkedHashSet<>();
        for (StreamMessage m : in.latest()) {
            robots.add(RobotId.of(m.key()));
        }
        for (RobotId id : robots) {
            RobotState r = in.world().robot(id);
            RobotShapes.trail(r, 2 * in.camera().metresPerPixel(), trail.vertices());
            RobotShapes.footprint(r, body.vertices());
            RobotShapes.heading(r, heading.vertices());
            RobotShapes.velocity(r, velocity.vertices());
        }
    }
}
