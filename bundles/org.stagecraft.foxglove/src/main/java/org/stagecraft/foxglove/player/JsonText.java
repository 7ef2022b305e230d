package org.stagecraft.foxglove.player;

/** JSON string and number text. */
final class JsonText {
    private JsonText() {
    }

    static void string(StringBuilder b, String s) {
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        b.append('"');
    }

    /** JSON has no NaN or infinities: those become null (the raw wire channels keep the exact value). */
    static void number(StringBuilder b, double v, boolean float32) {
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            b.append("null");
        } else {
            b.append(float32 ? Float.toString((float) v) : Double.toString(v));
        }
    }
}
