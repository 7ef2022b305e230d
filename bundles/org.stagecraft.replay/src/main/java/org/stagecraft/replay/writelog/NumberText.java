package org.stagecraft.replay.writelog;

/**
 * Numbers as writelog text. Player's readlog reads every number with {@code atof} (a C double, then
 * cast to float for float fields) or {@code atoi}, so any digits parse; writing the shortest text that
 * reads back to the same value makes a re-import exact where Player's own fixed {@code %.3f} loses digits.
 */
final class NumberText {
    private NumberText() {
    }

    /** The shortest decimal that reads back, through a double, to exactly {@code v}. */
    static String float32(float v) {
        String s = Float.toString(v);
        // Float.toString is shortest among floats; reading it as a double first and then rounding to
        // float (what readlog does) could in principle round differently, so check and fall back to
        // the double's own text, which is exact.
        return Float.compare((float) Double.parseDouble(s), v) == 0 ? s : Double.toString(v);
    }

    static String float64(double v) {
        return Double.toString(v);
    }

    static String uint32(int v) {
        return Integer.toUnsignedString(v);
    }

    /** Reads a number the way C's strtod does, including {@code inf} and {@code nan}. */
    static double parseDouble(String s) {
        String t = s.startsWith("+") ? s.substring(1) : s;
        String lower = t.toLowerCase(java.util.Locale.ROOT);
        switch (lower) {
            case "inf", "infinity" -> {
                return Double.POSITIVE_INFINITY;
            }
            case "-inf", "-infinity" -> {
                return Double.NEGATIVE_INFINITY;
            }
            case "nan", "-nan" -> {
                return Double.NaN;
            }
            default -> {
                if (lower.isEmpty() || lower.endsWith("d") || lower.endsWith("f") || lower.startsWith("0x")) {
                    // Java would accept a type suffix and C a hex float; neither is writelog's text
                    throw new NumberFormatException(s);
                }
                return Double.parseDouble(t);
            }
        }
    }

    /** A signed or unsigned 32-bit integer as written by {@code %d}, {@code %u}, {@code %+d} or {@code %04d}. */
    static long parseInteger(String s) {
        long v = Long.parseLong(s.startsWith("+") ? s.substring(1) : s);
        if (v < Integer.MIN_VALUE || v > 0xFFFFFFFFL) {
            throw new NumberFormatException(s + " is not a 32-bit integer");
        }
        return v;
    }
}
