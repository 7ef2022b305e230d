package org.stagecraft.recording.play;

import java.io.IOException;

/**
 * Compares bytes as they arrive with what was recorded, without keeping them: a replay loops for
 * hours, and the only question is whether the other side said exactly what the recording says. The
 * recorded bytes are read from their source as far as the comparison has got, so a large recording
 * is never held whole.
 */
final class ByteMatcher {
    private final ChunkSource expected;
    private byte[] current = new byte[0];
    private int at;
    private boolean expectedEnded;
    private long received;
    private long firstDifference = -1;

    ByteMatcher(ChunkSource expected) {
        this.expected = expected;
    }

    ByteMatcher(byte[] expected) {
        this(ChunkSource.of(java.util.List.of(new TimedChunk(0, expected))));
    }

    void accept(byte[] buffer, int length) throws IOException {
        for (int i = 0; i < length && firstDifference < 0; i++) {
            if (!moreExpected() || buffer[i] != current[at++]) {
                firstDifference = received + i;
            }
        }
        received += length;
    }

    /** Whether a recorded byte is left, moving to the next non-empty chunk when this one is used up. */
    private boolean moreExpected() throws IOException {
        while (at >= current.length && !expectedEnded) {
            TimedChunk c = expected.next();
            if (c == null) {
                expectedEnded = true;
            } else {
                current = c.data();
                at = 0;
            }
        }
        return at < current.length;
    }

    long received() {
        return received;
    }

    /** Whether everything received so far, and nothing more or less, is what was recorded. */
    boolean matchesWhole() throws IOException {
        return firstDifference < 0 && !moreExpected();
    }

    /** The offset of the first byte that differs (or is extra), or -1 if none does. */
    long firstDifference() {
        return firstDifference;
    }
}
