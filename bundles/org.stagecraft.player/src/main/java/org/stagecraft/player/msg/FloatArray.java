package org.stagecraft.player.msg;

import java.util.Arrays;

/** An immutable array of 32-bit floats (e.g. laser ranges). */
public final class FloatArray {
    private final float[] values;

    private FloatArray(float[] values) {
        this.values = values;
    }

    public static FloatArray of(float... values) {
        return new FloatArray(values.clone());
    }

    /** Takes ownership of a freshly decoded array; the caller must not keep or change it. */
    static FloatArray adopt(float[] values) {
        return new FloatArray(values);
    }

    public int size() {
        return values.length;
    }

    public float get(int i) {
        return values[i];
    }

    public float[] toArray() {
        return values.clone();
    }

    float[] raw() {
        return values;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof FloatArray f && Arrays.equals(values, f.values);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(values);
    }

    @Override
    public String toString() {
        return Arrays.toString(values);
    }
}
