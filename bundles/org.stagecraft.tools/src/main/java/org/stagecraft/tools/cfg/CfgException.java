package org.stagecraft.tools.cfg;

import java.nio.file.Path;

import org.eclipse.jdt.annotation.Nullable;

/** A Player configuration file that cannot be used; the message starts with {@code file:line:}. */
public final class CfgException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient @Nullable Path file;
    private final int line;

    public CfgException(@Nullable Path file, int line, String problem) {
        super(file + (line > 0 ? ":" + line : "") + ": " + problem);
        this.file = file;
        this.line = line;
    }

    public CfgException(@Nullable Path file, int line, String problem, Throwable cause) {
        this(file, line, problem);
        initCause(cause);
    }

    public @Nullable Path file() {
        return file;
    }

    /** 1-based, or 0 when the problem concerns the whole file (e.g. it cannot be read). */
    public int line() {
        return line;
    }
}
