package org.stagecraft.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.recording.trace.TraceFormatException;

/**
 * What a command could not read of a recording, said on stderr after the output, and the exit code
 * that follows from it ({@link ExitCode}): a spy log not closed properly, every damaged part skipped
 * (with the messages lost where the log knows), or the line where a trace stopped being readable.
 *
 * @param recovered    true if the log had no valid summary (not closed properly, or damaged there)
 * @param chunks       chunks of the log that could be read
 * @param lost         the damaged parts skipped, for people (a cut-off end among them)
 * @param messagesLost messages known to be lost with them
 * @param entries      entries read (a log's messages and events; a trace's banners, messages and pieces)
 * @param stopped      the problem a trace stopped at (nothing after it was read), or null
 */
record LogRecovery(boolean recovered, int chunks, List<String> lost, long messagesLost, long entries,
        @Nullable TraceFormatException stopped) {

    /** A trace read to its end. */
    static LogRecovery whole(long entries) {
        return new LogRecovery(false, 0, List.of(), 0, entries, null);
    }

    /** A trace read up to the problem it stopped at. */
    static LogRecovery stoppedAt(TraceFormatException problem, long entries) {
        return new LogRecovery(false, 0, List.of(), 0, entries, problem);
    }

    /** True if nothing at all could be read because of damage or a bad line. */
    boolean nothingRead() {
        return entries == 0 && (stopped != null || recovered || !lost.isEmpty());
    }

    /** True if part of the recording is missing from the output. */
    boolean anyLost() {
        return stopped != null || !lost.isEmpty();
    }

    /** Tells the user what was not read; @return the command's exit code. */
    int report(String command, Path file, PrintStream err) {
        String prefix = "stagecraft " + command + ": ";
        TraceFormatException s = stopped;
        if (s != null) {
            // the trace's own message names the file and the line once
            err.println(prefix + s.getMessage() + (entries > 0 ? "; nothing after that line was read" : ""));
            return entries > 0 ? ExitCode.LOSSES : ExitCode.FAILED;
        }
        if (recovered) {
            err.println(prefix + file + ": the log was not closed properly (no valid summary); "
                    + "read the " + chunks + " intact chunk" + (chunks == 1 ? "" : "s"));
        }
        for (String part : lost) {
            err.println(prefix + file + ": skipped " + part);
        }
        if (nothingRead()) {
            err.println(prefix + file + ": nothing could be read");
            return ExitCode.FAILED;
        }
        if (!lost.isEmpty()) {
            err.println(prefix + file + ": done with losses: " + lost.size() + (lost.size() == 1 ? " part" : " parts")
                    + " of the log could not be read" + (messagesLost > 0 ? " (" + messagesLost + " messages known lost)" : "")
                    + (lost.size() == 1 ? " and is" : " and are") + " missing from the output");
            return ExitCode.LOSSES;
        }
        return ExitCode.DONE;
    }
}
