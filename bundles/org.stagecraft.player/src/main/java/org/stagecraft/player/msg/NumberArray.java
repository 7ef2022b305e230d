package org.stagecraft.player.msg;

import java.lang.reflect.Array;
import java.util.Arrays;
import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;

/**
 * What {@link FloatArray} and {@link DoubleArray} share: an immutable array of numbers (a
 * {@code float[]} or a {@code double[]}, copied in and out, never changed), compared, hashed and
 * printed by its elements. The two stay separate types so that a 32-bit field keeps float precision
 * in decoding, encoding and printing.
 */
abstract sealed class NumberArray permits FloatArray, DoubleArray {
    private final Object values;

    NumberArray(Object values) {
        this.values = values;
    }

    public final int size() {
        return Array.getLength(values);
    }

    @Override
    public final boolean equals(@Nullable Object o) {
        return o != null && o.getClass() == getClass() && Objects.deepEquals(values, ((NumberArray) o).values);
    }

    @Override
    public final int hashCode() {
        return Arrays.deepHashCode(new Object[] { values });
    }

    @Override
    public final String toString() {
        String one = Arrays.deepToString(new Object[] { values }); // "[[1.0, 2.0]]"
        return one.substring(1, one.length() - 1);
    }
}
