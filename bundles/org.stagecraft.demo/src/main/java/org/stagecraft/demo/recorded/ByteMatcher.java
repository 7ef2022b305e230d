package org.stagecraft.demo.recorded;

/**
 * Compares bytes as they arrive with what was recorded, without keeping them: a replay loops for
 * hours, and the only question is whether the other side said exactly what the recording says.
 */
final class ByteMatcher {
    private final byte[] expected;
    private long received;
    private long firstDifference = -1;

    ByteMatcher(byte[] expected) {
        this.expected = expected;
    }

    void accept(byte[] buffer, int length) {
        for (int i = 0; i < length && firstDifference < 0; i++) {
            long at = received + i;
            if (at >= expected.length || buffer[i] != expected[(int) at]) {
                firstDifference = at;
            }
        }
        received += length;
    }

    long received() {
        return received;
    }

    /** Whether everything received so far, and nothing more or less, is what was recorded. */
    boolean matchesWhole() {
        return firstDifference < 0 && received == expected.length;
    }

    /** The offset of the first byte that differs (or is extra), or -1 if none does. */
    long firstDifference() {
        return firstDifference;
    }
}
