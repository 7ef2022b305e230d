package org.stagecraft.views;

import org.stagecraft.scene.LayerSpec;
import org.stagecraft.streams.DeliveryPolicy;

import com.jogamp.opengl.GL2;

/**
 * A visualisation of streams, drawn by a Robot View layer. Each frame runs three steps on the UI thread
 * with the view's GL context current:
 * <ol>
 * <li>{@link #acquire}: take the newest data of the layer's streams (and the world: poses, mounts) and
 * prepare CPU-side geometry; return whether anything changed. No GL here.</li>
 * <li>{@link #refresh}: only when {@code acquire} returned true, bring the GPU-side data (buffers,
 * textures) up to date.</li>
 * <li>{@link #render}: draw, in world coordinates (metres), with the layer's colour and transparency.</li>
 * </ol>
 * One instance per layer per view; contributed through the {@code org.stagecraft.views.renderers} extension
 * point (see docs/writing-a-renderer.md). Most renderers extend {@link ShapeRenderer}, which does steps 2
 * and 3 for vertex batches.
 */
public abstract class StreamRenderer {

    /** Step 1. @return true if {@link #refresh} must run before the next {@link #render} */
    protected abstract boolean acquire(RenderInput in);

    /** Step 2: upload what {@link #acquire} prepared. */
    protected abstract void refresh(GL2 gl);

    /** Step 3: draw. Blending is on (src alpha, one minus src alpha); the projection maps metres to pixels. */
    protected abstract void render(GL2 gl, LayerSpec layer, RenderInput in);

    /** Frees GPU resources; the GL context is current. */
    protected void dispose(GL2 gl) {
    }

    /**
     * How the layer's subscription is delivered. Latest-value (the default) keeps only the newest message
     * per stream so the view never lags; a renderer that accumulates (map tiles) asks for lossless.
     */
    public DeliveryPolicy deliveryPolicy() {
        return DeliveryPolicy.latestValue();
    }

    /** Runs the three steps for one frame. */
    public final void frame(GL2 gl, RenderInput in) {
        if (acquire(in)) {
            refresh(gl);
        }
        render(gl, in.layer(), in);
    }

    public final void disposeGl(GL2 gl) {
        dispose(gl);
    }
}
