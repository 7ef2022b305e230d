package org.stagecraft.streams;

/**
 * The type-id space of streams. Player's own message types are 1..6 (DATA, CMD, REQ, RESP_ACK,
 * SYNCH, RESP_NACK); the upper half of the 8-bit message-type space is reserved for user-defined,
 * derived streams published by {@link StreamProcessor}s.
 */
public final class StreamTypes {
    /** Smallest user-defined message type. */
    public static final int USER_MIN = 128;
    /** Largest user-defined message type. */
    public static final int USER_MAX = 255;
    /** Largest message type of any stream. */
    public static final int MESSAGE_TYPE_MAX = 255;
    /** Largest device (interface) type. */
    public static final int DEVICE_TYPE_MAX = 65535;
    /** Largest device index. */
    public static final int INDEX_MAX = 65535;
    /** Largest subtype. */
    public static final int SUBTYPE_MAX = 255;

    private StreamTypes() {
    }

    /** Whether {@code messageType} lies in the user-defined half, {@value #USER_MIN}..{@value #USER_MAX}. */
    public static boolean isUserDefined(int messageType) {
        return messageType >= USER_MIN && messageType <= USER_MAX;
    }
}
