package org.stagecraft.recording.trace;

import java.io.IOException;

/** A trace file that is not a valid player-trace; the message names the file and line. */
public final class TraceFormatException extends IOException {
    private static final long serialVersionUID = 1L;

    public TraceFormatException(String message) {
        super(message);
    }

    public TraceFormatException(String message, Throwable cause) {
        super(message, cause);
    }
}
