package org.stagecraft.cli;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.jdt.annotation.Nullable;

/** Checks a command's input file and says what is wrong with it, the same way for every command. */
final class InputFile {
    private InputFile() {
    }

    /**
     * @return the path, or null after printing "stagecraft COMMAND: FILE: why" (then the command exits
     *         with {@link ExitCode#FAILED})
     */
    static @Nullable Path readable(String command, String name, PrintStream err) {
        Path p = Path.of(name);
        String why = null;
        if (!Files.exists(p)) {
            why = "no such file";
        } else if (Files.isDirectory(p)) {
            why = "a folder, not a file";
        } else if (!Files.isRegularFile(p)) {
            why = "not a regular file";
        } else if (!Files.isReadable(p)) {
            why = "not readable (permission denied)";
        }
        if (why != null) {
            err.println("stagecraft " + command + ": " + p + ": " + why);
            return null;
        }
        return p;
    }
}
