package org.stagecraft.cli;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * Why a file could not be created, in words: Java's NoSuchFileException and AccessDeniedException
 * carry only the path as their message, which would print as "cannot write X: X".
 */
final class LogFileProblem {
    private LogFileProblem() {
    }

    static String reason(Path file, IOException e) {
        Path parent = file.toAbsolutePath().getParent();
        if (Files.isDirectory(file)) {
            return "it is a folder";
        }
        if (e instanceof NoSuchFileException) {
            return parent != null && !Files.isDirectory(parent) ? "no such folder " + parent : "no such file or folder";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied" + (parent != null && Files.isDirectory(parent) && !Files.isWritable(parent)
                    ? " (cannot create files in " + parent + ")" : "");
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return f.getReason();
        }
        return e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
    }
}
