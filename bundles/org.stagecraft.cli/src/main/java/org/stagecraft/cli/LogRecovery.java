package org.stagecraft.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;

/**
 * What a command could not read of a spy log: whether it was closed properly, and every damaged part
 * skipped (with the messages lost where the log knows). Printed to stderr after the output; a
 * command fails only when nothing at all could be read.
 *
 * @param recovered true if the log had no valid summary (not closed properly, or damaged there)
 * @param chunks    chunks of the log that could be read
 * @param lost      the damaged parts skipped, for people
 * @param entries   entries read (messages and events)
 */
record LogRecovery(boolean recovered, int chunks, List<String> lost, long entries) {

    /** A recording that needs no recovery (a trace). */
    static final LogRecovery NONE = new LogRecovery(false, 0, List.of(), -1);

    /** True if the log is damaged or cut off and not one entry could be read from it. */
    boolean nothingRead() {
        return entries == 0 && (recovered || !lost.isEmpty());
    }

    /** Tells the user what was lost; @return the command's exit status (1 when nothing could be read). */
    int report(String command, Path file, PrintStream err) {
        if (recovered) {
            err.println("stagecraft " + command + ": " + file + ": the log was not closed properly (no valid summary); "
                    + "read the " + chunks + " intact chunk" + (chunks == 1 ? "" : "s"));
        }
        for (String part : lost) {
            err.println("stagecraft " + command + ": " + file + ": skipped " + part);
        }
        if (nothingRead()) {
            err.println("stagecraft " + command + ": " + file + ": nothing could be read");
            return 1;
        }
        return 0;
    }
}
