package org.stagecraft.player.json;

/**
 * JSON string text, escaped as Gson's {@code JsonWriter} escapes it (not HTML-safe): {@code "} and
 * {@code \}, the short escapes {@code \t \b \n \r \f}, other control characters as six-character {@code \\u} escapes, and
 * U+2028/U+2029 (line and paragraph separators, which JavaScript source does not allow in strings).
 */
public final class JsonText {
    private JsonText() {
    }

    /** Appends {@code s} as a JSON string, or {@code null} for null. */
    public static void string(StringBuilder b, String s) {
        if (s == null) {
            b.append("null");
            return;
        }
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\t' -> b.append("\\t");
                case '\b' -> b.append("\\b");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\f' -> b.append("\\f");
                case '\u2028' -> b.append("\\u2028");
                case '\u2029' -> b.append("\\u2029");
                default -> {
                    if (c < 0x20) {
                        b.append("\\u00").append(Character.forDigit(c >> 4, 16)).append(Character.forDigit(c & 0xf, 16));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        b.append('"');
    }
}
