package org.stagecraft.views;

import java.nio.ByteBuffer;

/**
 * A frame read back from the GL back buffer (glReadPixels, RGBA, 8 bits per channel), rows from the bottom
 * as OpenGL counts them, so {@code rgb(column, row)} takes the same pixel coordinates as
 * {@link org.stagecraft.scene.Camera#pixelColumn} and {@link org.stagecraft.scene.Camera#pixelRow}.
 */
public record FramePixels(int width, int height, byte[] rgba) {

    public static FramePixels read(com.jogamp.opengl.GL gl, int width, int height) {
        ByteBuffer buf = ByteBuffer.allocateDirect(width * height * 4);
        gl.glPixelStorei(com.jogamp.opengl.GL.GL_PACK_ALIGNMENT, 1);
        gl.glReadPixels(0, 0, width, height, com.jogamp.opengl.GL.GL_RGBA, com.jogamp.opengl.GL.GL_UNSIGNED_BYTE, buf);
        byte[] out = new byte[width * height * 4];
        buf.get(out);
        return new FramePixels(width, height, out);
    }

    public boolean contains(int column, int row) {
        return column >= 0 && row >= 0 && column < width && row < height;
    }

    /** 0xRRGGBB of the pixel. */
    public int rgb(int column, int row) {
        if (!contains(column, row)) {
            throw new IndexOutOfBoundsException("pixel (" + column + ", " + row + ") outside " + width + " x " + height);
        }
        int i = 4 * (row * width + column);
        return ((rgba[i] & 0xFF) << 16) | ((rgba[i + 1] & 0xFF) << 8) | (rgba[i + 2] & 0xFF);
    }

    /** Number of pixels whose colour differs from {@code other}'s at the same place. */
    public int differingPixels(FramePixels other) {
        if (other.width != width || other.height != height) {
            throw new IllegalArgumentException("frames differ in size");
        }
        int n = 0;
        for (int i = 0; i < rgba.length; i += 4) {
            if (rgba[i] != other.rgba[i] || rgba[i + 1] != other.rgba[i + 1] || rgba[i + 2] != other.rgba[i + 2]) {
                n++;
            }
        }
        return n;
    }

    /** Number of pixels within {@code tolerance} (per channel) of {@code rgb}. */
    public int count(int rgb, int tolerance) {
        int n = 0;
        for (int row = 0; row < height; row++) {
            for (int col = 0; col < width; col++) {
                if (close(rgb(col, row), rgb, tolerance)) {
                    n++;
                }
            }
        }
        return n;
    }

    public static boolean close(int a, int b, int tolerance) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF)) > tolerance) {
                return false;
            }
        }
        return true;
    }

    /** The colour {@code rgb} drawn with opacity {@code alpha} over {@code below} (GL's SRC_ALPHA blend). */
    public static int blend(int rgb, double alpha, int below) {
        int out = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
            double c = ((rgb >> shift) & 0xFF) * alpha + ((below >> shift) & 0xFF) * (1 - alpha);
            out |= (int) Math.round(c) << shift;
        }
        return out;
    }

    /** The frame as a PNG-ready ARGB array, top row first (for screenshots). */
    public int[] argbTopDown() {
        int[] out = new int[width * height];
        for (int row = 0; row < height; row++) {
            for (int col = 0; col < width; col++) {
                out[(height - 1 - row) * width + col] = 0xFF000000 | rgb(col, row);
            }
        }
        return out;
    }
}
