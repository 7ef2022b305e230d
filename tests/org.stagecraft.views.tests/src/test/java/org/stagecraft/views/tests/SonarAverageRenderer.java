package org.stagecraft.views.tests;

import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RobotId;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.GlBatch;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.ShapeRenderer;

import com.jogamp.opengl.GL;

/**
 * The worked example of docs/writing-a-renderer.md: the mean range of a robot's sonar ring (a derived
 * stream, user type 128, payload a Double) drawn as a circle of that radius around the robot.
 */
public class SonarAverageRenderer extends ShapeRenderer {
    static final int SEGMENTS = 64;
    private final GlBatch circle = batch(new GlBatch(GL.GL_LINES, GlBatch.Tint.LAYER).size(2));

    @Override
    protected void build(RenderInput in) {
        for (StreamMessage m : in.latest()) {
            if (m.payload() instanceof Double mean) {
                Pose2 robot = in.world().robot(RobotId.of(m.key())).pose();
                for (int i = 0; i < SEGMENTS; i++) {
                    double a0 = 2 * Math.PI * i / SEGMENTS, a1 = 2 * Math.PI * (i + 1) / SEGMENTS;
                    circle.vertices().add(robot.x() + mean * Math.cos(a0), robot.y() + mean * Math.sin(a0));
                    circle.vertices().add(robot.x() + mean * Math.cos(a1), robot.y() + mean * Math.sin(a1));
                }
            }
        }
    }
}
