package org.stagecraft.views.renderers;

import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Blobfinder;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.Payloads;
import org.stagecraft.scene.shapes.BlobOverlay;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.views.RenderInput;
import org.stagecraft.views.StreamRenderer;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2;
import com.jogamp.opengl.fixedfunc.GLMatrixFunc;

/**
 * Blobfinder blobs in the camera's image frame, in a small overlay in the view's top-right corner (not
 * in the world: a blobfinder reports pixels, not positions). Each blob is a rectangle in its own colour.
 * A handful of rectangles per frame: drawn directly, no buffers to refresh.
 */
public class BlobfinderRenderer extends StreamRenderer {
    private final List<Blobfinder.Blobs> frames = new ArrayList<>();
    private long seen = -1;

    @Override
    protected boolean acquire(RenderInput in) {
        if (in.dataVersion() == seen) {
            return false;
        }
        seen = in.dataVersion();
        frames.clear();
        for (StreamMessage m : in.latest()) {
            MessageBody b = Payloads.body(m);
            if (b instanceof Blobfinder.Blobs blobs) {
                frames.add(blobs);
            }
        }
        return true;
    }

    @Override
    protected void refresh(GL2 gl) {
        // nothing on the GPU side
    }

    @Override
    protected void render(GL2 gl, LayerSpec layer, RenderInput in) {
        if (frames.isEmpty()) {
            return;
        }
        int w = in.camera().width(), h = in.camera().height();
        gl.glMatrixMode(GLMatrixFunc.GL_PROJECTION);
        gl.glPushMatrix();
        gl.glLoadIdentity();
        gl.glOrtho(0, w, 0, h, -1, 1);
        int stacked = 0;
        for (Blobfinder.Blobs f : frames) {
            BlobOverlay o = BlobOverlay.layout(f.width(), f.height(), w, h);
            double dy = -stacked * (o.top() - o.bottom() + BlobOverlay.MARGIN);
            stacked++;
            gl.glColor4f(0.1f, 0.1f, 0.1f, (float) layer.alpha());
            rect(gl, GL2.GL_QUADS, o.left(), o.bottom() + dy, o.right(), o.top() + dy);
            for (Blobfinder.Blob b : f.blobs()) {
                gl.glColor4f(((b.color() >> 16) & 0xFF) / 255f, ((b.color() >> 8) & 0xFF) / 255f, (b.color() & 0xFF) / 255f,
                        (float) layer.alpha());
                rect(gl, GL2.GL_QUADS, o.x(b.left()), o.y(b.bottom()) + dy, o.x(b.right()), o.y(b.top()) + dy);
            }
            gl.glColor4f(layer.red(), layer.green(), layer.blue(), 1);
            rect(gl, GL.GL_LINE_LOOP, o.left(), o.bottom() + dy, o.right(), o.top() + dy);
        }
        gl.glPopMatrix();
        gl.glMatrixMode(GLMatrixFunc.GL_MODELVIEW);
    }

    private static void rect(GL2 gl, int mode, double l, double b, double r, double t) {
        gl.glBegin(mode);
        gl.glVertex2d(l, b);
        gl.glVertex2d(r, b);
        gl.glVertex2d(r, t);
        gl.glVertex2d(l, t);
        gl.glEnd();
    }
}
