package org.stagecraft.cli;

/**
 * The command line's exit codes: one rule for every command (docs/robustness.md, "Exit codes").
 * Whatever is not done, or done only in part, is said on stderr with counts.
 */
final class ExitCode {
    /** Everything asked for was done. */
    static final int DONE = 0;
    /**
     * Nothing usable was done: the input could not be read at all (missing, a folder, not the format
     * its name or content promises, nothing readable in it), the output could not be written, the
     * spy could not start, or an internal error.
     */
    static final int FAILED = 1;
    /** The command line itself is wrong (unknown command or option, a missing or bad value). */
    static final int USAGE = 2;
    /**
     * Done with losses: the output is written, but part of the input could not be read and is
     * missing from it (a damaged chunk, a cut-off end, a bad line and what followed it), or the spy's
     * log stopped before the spy did.
     */
    static final int LOSSES = 3;

    private ExitCode() {
    }
}
