package org.stagecraft.replay.writelog;

/**
 * What a Stagecraft comment line says about the message line after it, where Player's format leaves
 * something open. Player's writelog writes an intensity after every laser range, zero when the scan
 * has none, so readlog always has as many intensities as ranges; a scan that had no intensities at
 * all (Stage sends some) is marked, on a comment line readlog skips, so that it re-imports exactly.
 */
enum LineNote {
    NONE(""),
    /** The next line is a laser scan without intensities (intensity_count 0). */
    NO_INTENSITIES("no-intensities");

    /** First value after {@code #} on a note line. */
    static final String PREFIX = "stagecraft-note";

    private final String word;

    LineNote(String word) {
        this.word = word;
    }

    String line() {
        return "# " + PREFIX + " " + word + "\n";
    }

    static LineNote of(String word) {
        for (LineNote n : values()) {
            if (n != NONE && n.word.equals(word)) {
                return n;
            }
        }
        return NONE;
    }
}
