package org.stagecraft.cli;

import java.nio.file.Path;

/**
 * The one-line message a command prints when reading a file fails in a way that is not a problem the
 * reader names itself (those are IOExceptions with the file, line and reason): running out of memory,
 * or a bug. Users get a sentence and what to do, never a stack trace.
 */
final class CommandFailure {
    private CommandFailure() {
    }

    static String describe(Path file, Throwable t) {
        if (t instanceof OutOfMemoryError) {
            return file + ": out of memory (maximum heap " + (Runtime.getRuntime().maxMemory() >> 20)
                    + " MiB); give the tool more with STAGECRAFT_JAVA_OPTS=-Xmx2g";
        }
        return file + ": internal error, please report it with the file: " + t;
    }
}
