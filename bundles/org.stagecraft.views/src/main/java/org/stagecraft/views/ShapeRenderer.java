package org.stagecraft.views;

import java.util.ArrayList;
import java.util.List;

import org.stagecraft.scene.LayerSpec;

import com.jogamp.opengl.GL2;

/**
 * A renderer made of {@link GlBatch}es: subclasses declare their batches once and fill their vertices in
 * {@link #build}; uploading and drawing (steps 2 and 3) happen here. {@link #build} runs only when the
 * layer's data or the world changed since the last frame.
 */
public abstract class ShapeRenderer extends StreamRenderer {
    private final List<GlBatch> batches = new ArrayList<>();
    private long seenData = -1, seenWorld = -1;
    private double seenMpp = -1;

    /** Declares a batch; batches draw in declaration order. */
    protected final GlBatch batch(GlBatch b) {
        batches.add(b);
        return b;
    }

    /** Fills the batches' vertices (they are cleared before). */
    protected abstract void build(RenderInput in);

    /** Whether geometry depends on the zoom (sizes in pixels); then a zoom also rebuilds. */
    protected boolean zoomDependent() {
        return false;
    }

    @Override
    protected boolean acquire(RenderInput in) {
        long world = in.world().version();
        double mpp = zoomDependent() ? in.camera().metresPerPixel() : 0;
        if (in.dataVersion() == seenData && world == seenWorld && mpp == seenMpp) {
            return false;
        }
        seenData = in.dataVersion();
        seenWorld = world;
        seenMpp = mpp;
        for (GlBatch b : batches) {
            b.vertices().clear();
        }
        build(in);
        return true;
    }

    @Override
    protected void refresh(GL2 gl) {
        for (GlBatch b : batches) {
            b.upload(gl);
        }
    }

    @Override
    protected void render(GL2 gl, LayerSpec layer, RenderInput in) {
        for (GlBatch b : batches) {
            b.draw(gl, layer);
        }
    }

    @Override
    protected void dispose(GL2 gl) {
        for (GlBatch b : batches) {
            b.dispose(gl);
        }
    }

    /** Vertices the batches hold after the last upload (a frame statistic for tests and the benchmark). */
    public int vertexCount() {
        int n = 0;
        for (GlBatch b : batches) {
            n += b.uploadedVertices();
        }
        return n;
    }
}
