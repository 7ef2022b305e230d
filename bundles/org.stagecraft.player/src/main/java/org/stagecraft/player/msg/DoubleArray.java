package org.stagecraft.player.msg;

/** An immutable array of 64-bit doubles (e.g. ranger ranges). */
public final class DoubleArray extends NumberArray {
    private final double[] values;

    private DoubleArray(double[] values) {
        super(values);
        this.values = values;
    }

    public static DoubleArray of(double... values) {
        return new DoubleArray(values.clone());
    }

    /** Takes ownership of a freshly decoded array; the caller must not keep or change it. */
    static DoubleArray adopt(double[] values) {
        return new DoubleArray(values);
    }

    public double get(int i) {
        return values[i];
    }

    public double[] toArray() {
        return values.clone();
    }

    double[] raw() {
        return values;
    }
}
