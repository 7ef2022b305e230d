package org.stagecraft.streams;

import java.util.Objects;

/**
 * Identifies one stream: who sends it ({@code source}), to whom ({@code destination}), and its type,
 * which is the message type plus the device type (interface code, index, subtype). Addresses are
 * {@code host:port} texts such as {@code "127.0.0.1:40312"}; any non-blank text without whitespace is
 * accepted, so derived streams may use names of their own.
 *
 * @param source      sender address, e.g. {@code "127.0.0.1:6665"}
 * @param destination receiver address
 * @param messageType 0..255; Player uses 1..6, 128..255 are user-defined ({@link StreamTypes})
 * @param deviceType  interface code, 0..65535
 * @param index       device index, 0..65535
 * @param subtype     0..255
 */
public record StreamKey(String source, String destination, int messageType, int deviceType, int index, int subtype) {

    public StreamKey {
        checkAddress("source", source);
        checkAddress("destination", destination);
        checkRange("messageType", messageType, StreamTypes.MESSAGE_TYPE_MAX);
        checkRange("deviceType", deviceType, StreamTypes.DEVICE_TYPE_MAX);
        checkRange("index", index, StreamTypes.INDEX_MAX);
        checkRange("subtype", subtype, StreamTypes.SUBTYPE_MAX);
    }

    /** Whether this is a user-defined (derived) stream: message type 128 or above. */
    public boolean isUserDefined() {
        return messageType >= StreamTypes.USER_MIN;
    }

    /** The same stream addresses and device with another message type, e.g. a derived stream's key. */
    public StreamKey withMessageType(int newMessageType) {
        return new StreamKey(source, destination, newMessageType, deviceType, index, subtype);
    }

    /** The same stream with another subtype. */
    public StreamKey withSubtype(int newSubtype) {
        return new StreamKey(source, destination, messageType, deviceType, index, newSubtype);
    }

    private static void checkAddress(String what, String value) {
        Objects.requireNonNull(value, what);
        if (value.isBlank()) {
            throw new IllegalArgumentException(what + " is blank");
        }
        for (int i = 0; i < value.length(); i++) {
            if (Character.isWhitespace(value.charAt(i))) {
                throw new IllegalArgumentException(what + " '" + value + "' contains whitespace");
            }
        }
    }

    static void checkRange(String what, int value, int max) {
        if (value < 0 || value > max) {
            throw new IllegalArgumentException(what + " " + value + " is outside 0.." + max);
        }
    }
}
