package org.stagecraft.mcap;

import java.io.IOException;

/** Bytes that are not what MCAP says (not MCAP, a record that does not fit, a bad CRC). */
public class McapFormatException extends IOException {
    private static final long serialVersionUID = 1L;

    public McapFormatException(String message) {
        super(message);
    }

    public McapFormatException(String message, Throwable cause) {
        super(message, cause);
    }
}
