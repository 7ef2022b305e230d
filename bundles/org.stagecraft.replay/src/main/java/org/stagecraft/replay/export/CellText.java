package org.stagecraft.replay.export;

import java.util.HexFormat;

/**
 * A field value as text that reads back to the same value: integers as they are, a float32 as the
 * shortest text that parses to the same float, a float64 as the shortest that parses to the same
 * double, opaque bytes in hex.
 */
final class CellText {
    private CellText() {
    }

    static String of(Object v) {
        return switch (v) {
            case null -> "";
            case Float f -> Float.toString(f);
            case Double d -> Double.toString(d);
            case byte[] b -> HexFormat.of().formatHex(b);
            default -> v.toString();
        };
    }

    /** Log time in seconds with every nanosecond digit (exact, unlike a double). */
    static String seconds(long nanos) {
        long s = Math.floorDiv(nanos, 1_000_000_000L);
        long ns = Math.floorMod(nanos, 1_000_000_000L);
        return s + "." + String.format("%09d", ns);
    }
}
