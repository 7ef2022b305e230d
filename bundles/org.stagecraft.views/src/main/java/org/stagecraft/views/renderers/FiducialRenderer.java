package org.stagecraft.views.renderers;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Fiducial;
import org.stagecraft.scene.DeviceAddress;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.Pose2;
import org.stagecraft.scene.shapes.SensorShapes;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.GlBatch;
import org.stagecraft.views.GlBatch.Tint;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.ShapeRenderer;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2;
import com.jogamp.opengl.util.gl2.GLUT;

/**
 * Fiducials (fiducial DATA SCAN): a marker at each detected fiducial's pose (relative to the detector,
 * which sits at its mounting pose), a line from the detector to it, and the fiducial's id beside it.
 */
public class FiducialRenderer extends ShapeRenderer {
    private record Label(double x, double y, String text) {
    }

    private final GlBatch sightLines = batch(new GlBatch(GL.GL_LINES, new Tint(1, 0.4f, false)));
    private final GlBatch markers = batch(new GlBatch(GL.GL_TRIANGLES, Tint.LAYER));
    private final GlBatch headings = batch(new GlBatch(GL.GL_LINES, new Tint(0.5f, 1, true)).size(2));
    private final List<Label> labels = new ArrayList<>();
    private @Nullable GLUT glut;

    @Override
    protected void build(RenderInput in) {
        labels.clear();
        for (StreamMessage m : in.latest()) {
            MessageBody b = Payloads.body(m);
            if (!(b instanceof Fiducial.Scan scan)) {
                continue;
            }
            Pose2 sensor = in.world().devicePose(DeviceAddress.of(m.key()));
            for (Fiducial.Item item : scan.fiducials()) {
                Pose2 f = sensor.compose(Pose2.of(item.pose()));
                sightLines.vertices().add(sensor.x(), sensor.y());
                sightLines.vertices().add(f.x(), f.y());
                SensorShapes.square(f.x(), f.y(), 0.15, markers.vertices());
                headings.vertices().add(f.x(), f.y());
                headings.vertices().add(f.toParentX(0.2, 0), f.toParentY(0.2, 0));
                labels.add(new Label(f.x() + 0.12, f.y() + 0.12, Integer.toString(item.id())));
            }
        }
    }

    @Override
    protected void render(GL2 gl, LayerSpec layer, RenderInput in) {
        super.render(gl, layer, in);
        if (glut == null) {
            glut = new GLUT();
        }
        gl.glColor4f(layer.red() * 0.5f, layer.green() * 0.5f, layer.blue() * 0.5f, 1);
        for (Label l : labels) {
            gl.glRasterPos2d(l.x(), l.y());
            glut.glutBitmapString(GLUT.BITMAP_HELVETICA_12, l.text());
        }
    }
}
