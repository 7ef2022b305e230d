package org.stagecraft.player.msg;

/** An immutable array of 32-bit floats (e.g. laser ranges). */
public final class FloatArray extends NumberArray {
    private final float[] values;

    private FloatArray(float[] values) {
        super(values);
        this.values = values;
    }

    public static FloatArray of(float... values) {
        return new FloatArray(values.clone());
    }

    /** Takes ownership of a freshly decoded array; the caller must not keep or change it. */
    static FloatArray adopt(float[] values) {
        return new FloatArray(values);
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
}
