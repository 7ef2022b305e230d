package org.stagecraft.tools.session;

import org.eclipse.jdt.annotation.Nullable;

/**
 * A robot session could not start. The message says what failed and where (cfg file and line,
 * port, program); when this is thrown, everything the session had started is stopped again.
 */
public final class SessionException extends Exception {
    private static final long serialVersionUID = 1L;

    public SessionException(String message, @Nullable Throwable cause) {
        super(message, cause);
    }
}
