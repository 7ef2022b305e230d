package org.stagecraft.replay.writelog;

import java.util.List;

/** The payload tokens of one writelog line, read in order, with errors that name the token. */
final class Tokens {
    private final List<String> tokens;
    private int next;

    /** @param start index of the first payload token (after the 7 header tokens) */
    Tokens(List<String> tokens, int start) {
        this.tokens = tokens;
        this.next = start;
    }

    private String take(String what) throws WritelogSyntaxException {
        if (next >= tokens.size()) {
            throw new WritelogSyntaxException("the line ends where " + what + " should be (value " + (next + 1) + ")");
        }
        return tokens.get(next++);
    }

    double float64(String what) throws WritelogSyntaxException {
        String t = take(what);
        try {
            return NumberText.parseDouble(t);
        } catch (NumberFormatException e) {
            throw new WritelogSyntaxException(what + " '" + t + "' (value " + next + ") is not a number");
        }
    }

    float float32(String what) throws WritelogSyntaxException {
        return (float) float64(what);
    }

    /** An integer field (signed or unsigned 32-bit), as the int the codec keeps. */
    int int32(String what) throws WritelogSyntaxException {
        String t = take(what);
        try {
            return (int) NumberText.parseInteger(t);
        } catch (NumberFormatException e) {
            throw new WritelogSyntaxException(what + " '" + t + "' (value " + next + ") is not an integer");
        }
    }

    /** A count of things that follow; each needs at least {@code tokensEach} more values. */
    int count(String what, int tokensEach) throws WritelogSyntaxException {
        int n = int32(what);
        if (n < 0 || (long) n * tokensEach > tokens.size() - next) {
            throw new WritelogSyntaxException(what + " " + Integer.toUnsignedString(n) + " needs "
                    + (long) Integer.toUnsignedLong(n) * tokensEach + " more values but the line has "
                    + (tokens.size() - next));
        }
        return n;
    }

    boolean atEnd() {
        return next >= tokens.size();
    }

    int remaining() {
        return tokens.size() - next;
    }

    /** Refuses values after the payload: a count that says less than the line holds. */
    void expectEnd() throws WritelogSyntaxException {
        if (next < tokens.size()) {
            throw new WritelogSyntaxException((tokens.size() - next) + " values left over after the payload");
        }
    }
}
