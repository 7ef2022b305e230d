package org.stagecraft.scene.shapes;

import java.util.Arrays;

/** A growable array of floats (vertex x,y pairs) that is reused frame after frame without garbage. */
public final class FloatList {
    private float[] a = new float[256];
    private int size;

    public void clear() {
        size = 0;
    }

    public void add(double x, double y) {
        if (size + 2 > a.length) {
            a = Arrays.copyOf(a, a.length * 2);
        }
        a[size++] = (float) x;
        a[size++] = (float) y;
    }

    /** Number of floats (twice the number of vertices). */
    public int size() {
        return size;
    }

    public int vertices() {
        return size / 2;
    }

    /** The backing array; only the first {@link #size()} floats are meaningful. */
    public float[] array() {
        return a;
    }

    public float get(int i) {
        if (i >= size) {
            throw new IndexOutOfBoundsException(i + " >= " + size);
        }
        return a[i];
    }
}
