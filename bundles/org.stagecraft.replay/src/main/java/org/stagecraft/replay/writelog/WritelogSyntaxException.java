package org.stagecraft.replay.writelog;

/** A writelog line that does not say what its header promises; the message says what and where. */
final class WritelogSyntaxException extends Exception {
    private static final long serialVersionUID = 1L;

    WritelogSyntaxException(String message) {
        super(message);
    }
}
