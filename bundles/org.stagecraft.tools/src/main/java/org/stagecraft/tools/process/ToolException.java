package org.stagecraft.tools.process;

/** A tool could not be started or did not become ready; the message names the tool and the cause. */
public final class ToolException extends Exception {
    private static final long serialVersionUID = 1L;

    public ToolException(String message) {
        super(message);
    }

    public ToolException(String message, Throwable cause) {
        super(message, cause);
    }
}
