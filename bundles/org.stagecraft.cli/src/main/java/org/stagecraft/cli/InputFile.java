package org.stagecraft.cli;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.jdt.annotation.Nullable;

/** Checks a command's FILE argument and explains what is wrong with it. */
final class InputFile {
    private InputFile() {
    }

    /** @return the path, or null after printing why it cannot be read */
    static @Nullable Path require(String command, String[] args, PrintStream err) {
        if (args.length != 1) {
            err.println("usage: stagecraft " + command + " FILE");
            return null;
        }
        Path p = Path.of(args[0]);
        if (!Files.exists(p)) {
            err.println("stagecraft " + command + ": " + p + ": no such file");
            return null;
        }
        if (!Files.isRegularFile(p) || !Files.isReadable(p)) {
            err.println("stagecraft " + command + ": " + p + ": not a readable file");
            return null;
        }
        return p;
    }
}
