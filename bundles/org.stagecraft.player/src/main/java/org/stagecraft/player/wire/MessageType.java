package org.stagecraft.player.wire;

import org.eclipse.jdt.annotation.Nullable;

/** Player message types (player.h, PLAYER_MSGTYPE_*). */
public enum MessageType {
    DATA(1), CMD(2), REQ(3), RESP_ACK(4), SYNCH(5), RESP_NACK(6);

    /** values() copies its array at every call; this is looked up for every message. */
    private static final MessageType[] BY_CODE = values();

    private final int code;

    MessageType(int code) {
        this.code = code;
    }

    public int code() {
        return code;
    }

    /** @return the type for a wire code, or null when the code is not a Player message type */
    public static @Nullable MessageType of(int code) {
        return code >= 1 && code <= 6 ? BY_CODE[code - 1] : null;
    }

    /** Replies use the layout of the request they answer. */
    public MessageType layoutKind() {
        return this == RESP_ACK || this == RESP_NACK ? REQ : this;
    }
}
