package org.stagecraft.replay.log;

import java.io.IOException;
import java.nio.file.Path;

/**
 * Opens any log a user can give: a spy log, a recorded trace or a Player writelog file, recognised
 * by content rather than by name.
 */
public final class SessionLogs {
    private SessionLogs() {
    }

    /**
     * Opens {@code file}. A truncated or partly corrupt file opens with what is readable and says
     * where it stopped in {@link SessionLog#problems()}.
     *
     * @throws IOException naming the file when it cannot be read or is none of the known formats
     */
    public static SessionLog open(Path file) throws IOException {
        throw new UnsupportedOperationException("not built yet");
    }
}
