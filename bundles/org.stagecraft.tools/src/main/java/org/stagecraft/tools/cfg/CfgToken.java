package org.stagecraft.tools.cfg;

/**
 * One token of a Player configuration file, with where it is in the text so that a rewrite can
 * replace exactly this token and leave comments and layout alone.
 *
 * @param text  for {@link Kind#STRING} the contents without the quotes, else the token as written
 * @param start offset of the first character (the opening quote of a string)
 * @param end   offset after the last character (after the closing quote of a string)
 */
public record CfgToken(Kind kind, String text, int line, int start, int end) {
    public enum Kind {
        WORD, STRING, OPEN_PAREN, CLOSE_PAREN, OPEN_BRACKET, CLOSE_BRACKET
    }

    public boolean is(Kind k) {
        return kind == k;
    }
}
