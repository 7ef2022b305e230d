package org.stagecraft.replay.log;

/**
 * Something wrong with a log file, said where it is.
 *
 * @param where     a place in the file a user can find, e.g. "byte 1048576" or "line 12"
 * @param timeNanos the log time at which it happened (the last readable time for a cut-off file)
 * @param text      what is wrong and what was done about it
 * @param dataLost  true when part of the recording could not be read because of it (a skipped line,
 *                  a damaged chunk, the rest of a trace after a bad line); false for a note that
 *                  loses nothing, e.g. a spy log without its summary whose records are all whole
 */
public record LogProblem(String where, long timeNanos, String text, boolean dataLost) {

    /** A problem that lost part of the recording. */
    public LogProblem(String where, long timeNanos, String text) {
        this(where, timeNanos, text, true);
    }

    @Override
    public String toString() {
        return where + ": " + text;
    }
}
