package org.stagecraft.replay.log;

/**
 * Something wrong with a log file, said where it is.
 *
 * @param where    a place in the file a user can find, e.g. "byte 1048576" or "line 12"
 * @param timeNanos the log time at which it happened (the last readable time for a cut-off file)
 * @param text     what is wrong and what was done about it
 */
public record LogProblem(String where, long timeNanos, String text) {
    @Override
    public String toString() {
        return where + ": " + text;
    }
}
