package org.stagecraft.views.renderers;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Bumper;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.RobotState;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.GlBatch;
import org.stagecraft.views.GlBatch.Tint;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.ShapeRenderer;

import com.jogamp.opengl.GL;

/**
 * Bumpers (bumper DATA STATE): each bumper as a bar at its mounting pose (bumper GET_GEOM reply), pressed
 * ones opaque and thick, the others faint. Until the geometry is seen the bumpers are spread around the
 * robot's footprint.
 */
public class BumperRenderer extends ShapeRenderer {
    private final GlBatch idle = batch(new GlBatch(GL.GL_LINES, new Tint(1, 0.4f, false)).size(2));
    private final GlBatch pressed = batch(new GlBatch(GL.GL_LINES, new Tint(1, 1, true)).size(5));

    @Override
    protected void build(RenderInput in) {
        for (StreamMessage m : in.latest()) {
            MessageBody b = Payloads.body(m);
            if (!(b instanceof Bumper.State s)) {
                continue;
            }
            DeviceAddress dev = DeviceAddress.of(m.key());
            RobotState robot = in.world().robot(dev.robot());
            MessageBody g = in.world().geometry(dev);
            int n = s.bumpers().size();
            for (int i = 0; i < n; i++) {
                Pose2 at;
                double length;
                if (g instanceof Bumper.Geom geom && i < geom.bumperDef().size()) {
                    at = robot.pose().compose(Pose2.of(geom.bumperDef().get(i).pose()));
                    length = geom.bumperDef().get(i).length();
                } else {
                    double a = 2 * Math.PI * i / n, rad = Math.max(robot.body().length(), robot.body().width()) / 2;
                    at = robot.pose().compose(new Pose2(rad * Math.cos(a), rad * Math.sin(a), a));
                    length = 2 * Math.PI * rad / Math.max(1, n) * 0.8;
                }
                GlBatch target = s.bumpers().unsigned(i) != 0 ? pressed : idle;
                // the bar lies across the bumper's heading
                target.vertices().add(at.toParentX(0, -length / 2), at.toParentY(0, -length / 2));
                target.vertices().add(at.toParentX(0, length / 2), at.toParentY(0, length / 2));
            }
        }
    }
}
