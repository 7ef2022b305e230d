package org.stagecraft.views;

import java.nio.FloatBuffer;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.shapes.FloatList;

import com.jogamp.common.nio.Buffers;
import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2;
import com.jogamp.opengl.fixedfunc.GLPointerFunc;

/**
 * One primitive list (triangles, lines or points) in world coordinates with one colour, held in a
 * streamed vertex buffer: filled on the CPU in acquire, uploaded in refresh (GL_STREAM_DRAW, the cheapest
 * path for data that changes every frame on Mesa), drawn in render.
 */
public final class GlBatch {
    /** How a batch's colour relates to its layer's. */
    public record Tint(float shade, float alphaScale, boolean opaque) {
        public static final Tint LAYER = new Tint(1, 1, false);
    }

    private final int mode;
    private final FloatList vertices = new FloatList();
    private Tint tint;
    private float size = 1;
    private @Nullable FloatBuffer staging;
    private int vbo, uploaded;

    /** @param mode GL_TRIANGLES, GL_LINES or GL_POINTS */
    public GlBatch(int mode, Tint tint) {
        this.mode = mode;
        this.tint = tint;
    }

    /** Point size or line width in pixels. */
    public GlBatch size(float pixels) {
        size = pixels;
        return this;
    }

    public GlBatch tint(Tint t) {
        tint = t;
        return this;
    }

    /** The vertices to fill in acquire (cleared by the caller). */
    public FloatList vertices() {
        return vertices;
    }

    public void upload(GL2 gl) {
        int n = vertices.size();
        if (staging == null || staging.capacity() < n) {
            staging = Buffers.newDirectFloatBuffer(Math.max(256, Integer.highestOneBit(Math.max(1, n)) * 2));
        }
        staging.clear();
        staging.put(vertices.array(), 0, n).flip();
        if (vbo == 0) {
            int[] ids = new int[1];
            gl.glGenBuffers(1, ids, 0);
            vbo = ids[0];
        }
        gl.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo);
        gl.glBufferData(GL.GL_ARRAY_BUFFER, (long) n * Float.BYTES, staging, GL2.GL_STREAM_DRAW);
        gl.glBindBuffer(GL.GL_ARRAY_BUFFER, 0);
        uploaded = vertices.vertices();
    }

    public void draw(GL2 gl, LayerSpec layer) {
        if (uploaded == 0) {
            return;
        }
        float a = tint.opaque() ? 1f : (float) layer.alpha() * tint.alphaScale();
        gl.glColor4f(shade(layer.red()), shade(layer.green()), shade(layer.blue()), a);
        if (mode == GL.GL_POINTS) {
            gl.glPointSize(size);
        } else if (mode == GL.GL_LINES || mode == GL.GL_LINE_STRIP) {
            gl.glLineWidth(size);
        }
        gl.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo);
        gl.glEnableClientState(GLPointerFunc.GL_VERTEX_ARRAY);
        gl.glVertexPointer(2, GL.GL_FLOAT, 0, 0L);
        gl.glDrawArrays(mode, 0, uploaded);
        gl.glDisableClientState(GLPointerFunc.GL_VERTEX_ARRAY);
        gl.glBindBuffer(GL.GL_ARRAY_BUFFER, 0);
    }

    /** Vertices drawn by the last {@link #draw} (after the last upload). */
    public int uploadedVertices() {
        return uploaded;
    }

    public void dispose(GL2 gl) {
        if (vbo != 0) {
            gl.glDeleteBuffers(1, new int[] { vbo }, 0);
            vbo = 0;
        }
    }

    private float shade(float c) {
        return tint.shade() <= 1 ? c * tint.shade() : c + (1 - c) * (tint.shade() - 1);
    }
}
