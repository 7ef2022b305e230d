package org.stagecraft.spy.log;


/** A spy log whose bytes are not what its format says (not MCAP, a corrupt record, a bad CRC). */
public final class SpyLogFormatException extends org.stagecraft.mcap.McapFormatException {
    private static final long serialVersionUID = 1L;

    public SpyLogFormatException(String message) {
        super(message);
    }

    public SpyLogFormatException(String message, Throwable cause) {
        super(message, cause);
    }
}
