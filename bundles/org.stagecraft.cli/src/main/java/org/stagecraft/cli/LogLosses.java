package org.stagecraft.cli;

import java.io.PrintStream;

import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.log.SessionLog;

/**
 * What a command that reads a log through {@link SessionLog} (export, replay) could not read of it,
 * said on stderr once the log has been read (damage inside an indexed log is found only then), and
 * the exit code that follows ({@link ExitCode}).
 */
final class LogLosses {
    private LogLosses() {
    }

    /** Prints every problem, naming the file once each; @return how many lost part of the recording. */
    static long print(String command, SessionLog log, PrintStream err) {
        long lost = 0;
        for (LogProblem p : log.problems()) {
            err.println("stagecraft " + command + ": " + log.path() + ": " + p);
            if (p.dataLost()) {
                lost++;
            }
        }
        return lost;
    }

    /**
     * Prints every problem and, when any lost data, a last line saying so; @return {@link ExitCode#LOSSES}
     * if any lost data, else {@link ExitCode#DONE}.
     */
    static int report(String command, SessionLog log, PrintStream err) {
        long lost = print(command, log, err);
        if (lost == 0) {
            return ExitCode.DONE;
        }
        err.println("stagecraft " + command + ": " + log.path() + ": done with losses: " + lost + " part"
                + (lost == 1 ? " of the log (above) could not be read and is" : "s of the log (above) could not be read and are")
                + " missing from what " + command + " " + (command.equals("export") ? "wrote" : "served"));
        return ExitCode.LOSSES;
    }
}
