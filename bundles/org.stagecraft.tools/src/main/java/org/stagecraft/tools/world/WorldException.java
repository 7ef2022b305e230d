package org.stagecraft.tools.world;

/** The world cannot be frozen: the driver cannot be built, or Player's world driver does not answer. */
public final class WorldException extends Exception {
    private static final long serialVersionUID = 1L;

    public WorldException(String message) {
        super(message);
    }

    public WorldException(String message, Throwable cause) {
        super(message, cause);
    }
}
