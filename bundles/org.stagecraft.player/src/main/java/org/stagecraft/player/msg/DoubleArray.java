package org.stagecraft.player.msg;

import java.util.Arrays;

/** An immutable array of 64-bit doubles (e.g. ranger ranges). */
public final class DoubleArray {
    private final double[] values;

    private DoubleArray(double[] values) {
        this.values = values;
    }

    public static DoubleArray of(double... values) {
        return new DoubleArray(values.clone());
    }

    /** Takes ownership of a freshly decoded array; the caller must not keep or change it. */
    static DoubleArray adopt(double[] values) {
        return new DoubleArray(values);
    }

    public int size() {
        return values.length;
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

    @Override
    public boolean equals(Object o) {
        return o instanceof DoubleArray f && Arrays.equals(values, f.values);
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
