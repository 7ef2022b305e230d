package org.stagecraft.recording.play;

import java.io.IOException;

import org.eclipse.jdt.annotation.Nullable;

/** A recording that cannot be replayed; the message names the file and, for a corrupt one, the line. */
public final class RecordingException extends IOException {
    private static final long serialVersionUID = 1L;

    public RecordingException(String message, @Nullable Throwable cause) {
        super(message, cause);
    }
}
