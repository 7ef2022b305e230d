package org.stagecraft.tools.cfg;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Splits a Player configuration file into tokens: words (names, numbers), double-quoted strings,
 * parentheses and brackets. {@code #} starts a comment up to the end of the line. Strings may not
 * span lines (Player's own reader does not accept that either), so a missing closing quote is
 * reported on the line where the string starts rather than far below.
 */
final class CfgLexer {
    private CfgLexer() {
    }

    static List<CfgToken> tokens(Path file, String text) throws CfgException {
        List<CfgToken> out = new ArrayList<>();
        int line = 1;
        int i = 0;
        int n = text.length();
        while (i < n) {
            char c = text.charAt(i);
            if (c == '\n') {
                line++;
                i++;
            } else if (Character.isWhitespace(c)) {
                i++;
            } else if (c == '#') {
                while (i < n && text.charAt(i) != '\n') {
                    i++;
                }
            } else if (c == '"') {
                int close = i + 1;
                while (close < n && text.charAt(close) != '"' && text.charAt(close) != '\n') {
                    close++;
                }
                if (close >= n || text.charAt(close) != '"') {
                    throw new CfgException(file, line, "string has no closing quote: " + excerpt(text, i));
                }
                out.add(new CfgToken(CfgToken.Kind.STRING, text.substring(i + 1, close), line, i, close + 1));
                i = close + 1;
            } else if (c == '(' || c == ')' || c == '[' || c == ']') {
                CfgToken.Kind k = switch (c) {
                    case '(' -> CfgToken.Kind.OPEN_PAREN;
                    case ')' -> CfgToken.Kind.CLOSE_PAREN;
                    case '[' -> CfgToken.Kind.OPEN_BRACKET;
                    default -> CfgToken.Kind.CLOSE_BRACKET;
                };
                out.add(new CfgToken(k, String.valueOf(c), line, i, i + 1));
                i++;
            } else {
                int start = i;
                while (i < n && !Character.isWhitespace(text.charAt(i)) && "()[]\"#".indexOf(text.charAt(i)) < 0) {
                    i++;
                }
                out.add(new CfgToken(CfgToken.Kind.WORD, text.substring(start, i), line, start, i));
            }
        }
        return out;
    }

    private static String excerpt(String text, int from) {
        int end = text.indexOf('\n', from);
        String s = text.substring(from, end < 0 ? text.length() : end);
        return s.length() > 60 ? s.substring(0, 60) + "..." : s;
    }
}
