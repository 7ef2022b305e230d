package org.stagecraft.recording.trace;

import java.io.IOException;

import org.eclipse.jdt.annotation.Nullable;

/**
 * A trace file that is not a valid player-trace. The message is "FILE:LINE: REASON" ("FILE: REASON"
 * when no line is concerned); the parts are kept apart too, so that a caller which names the file or
 * the line itself says each once.
 */
public final class TraceFormatException extends IOException {
    private static final long serialVersionUID = 1L;

    private final String file;
    private final long line;
    private final String reason;

    /**
     * @param line the 1-based line the problem is on, or 0 when it concerns the whole file (e.g. an
     *             empty one)
     */
    public TraceFormatException(String file, long line, String reason, @Nullable Throwable cause) {
        super(file + (line > 0 ? ":" + line : "") + ": " + reason, cause);
        this.file = file;
        this.line = line;
        this.reason = reason;
    }

    public TraceFormatException(String file, long line, String reason) {
        this(file, line, reason, null);
    }

    /** The file's name as the reader was given it. */
    public String file() {
        return file;
    }

    /** The 1-based line the problem is on, or 0 when it concerns the whole file. */
    public long line() {
        return line;
    }

    /** What is wrong, without the file and the line. */
    public String reason() {
        return reason;
    }
}
