package org.stagecraft.player.msg;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;

/** FloatArray and DoubleArray: immutable, compared and printed by their elements, never equal to each other. */
class NumberArrayTest {

    @Test
    void equalByElementsWithinATypeOnly() {
        assertEquals(FloatArray.of(1f, 2.5f), FloatArray.of(1f, 2.5f));
        assertEquals(FloatArray.of(1f, 2.5f).hashCode(), FloatArray.of(1f, 2.5f).hashCode());
        assertNotEquals(FloatArray.of(1f, 2.5f), FloatArray.of(1f, 2f));
        assertEquals(DoubleArray.of(1, Double.NaN), DoubleArray.of(1, Double.NaN), "NaN equals NaN, as in Arrays.equals");
        assertNotEquals(DoubleArray.of(0.0), DoubleArray.of(-0.0), "-0 is another value, as in Arrays.equals");
        assertNotEquals(FloatArray.of(1f), DoubleArray.of(1), "a float array is no double array");
    }

    @Test
    void sizeElementsAndTextAreTheElementsAsGiven() {
        float[] given = { 0.1f, 8f };
        FloatArray a = FloatArray.of(given);
        given[0] = 99;
        assertEquals(2, a.size());
        assertEquals(0.1f, a.get(0));
        assertArrayEquals(new float[] { 0.1f, 8f }, a.toArray());
        a.toArray()[1] = 7;
        assertEquals(8f, a.get(1), "copies out, never shares");
        assertEquals("[0.1, 8.0]", a.toString(), "float precision in text");
        assertEquals("[0.1, 8.0]", DoubleArray.of(0.1, 8).toString());
        assertEquals(0, DoubleArray.of().size());
        assertEquals("[]", DoubleArray.of().toString());
    }
}
