package org.stagecraft.spy.hold;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamPattern;

/**
 * Where the spy publishes what its robot hold does, on the stream bus. The message types are at the
 * top of the user-defined range (stream processors count up from 128).
 *
 * <ul>
 * <li>{@link #STATE}: a {@link HoldState} every time the hold changes (enabled, held, reasons);
 * subscribe latest-value for a status line.</li>
 * <li>{@link #actionKey}: a {@link HoldAction} per injected or held-back message, keyed like the
 * connection's client-to-server messages ({@link SpyStreams#key}) with type {@link #INJECTED_TYPE} or
 * {@link #HELD_BACK_TYPE} and the message's device and subtype; a robot data breakpoint's hit and the
 * passing on of the messages it held back are keyed like the connection's server-to-client messages,
 * with type {@link #BREAK_TYPE} or {@link #PASSED_ON_TYPE}.</li>
 * </ul>
 */
public final class HoldStreams {
    public static final int WORLD_TYPE = 250;
    public static final int PASSED_ON_TYPE = 251;
    public static final int BREAK_TYPE = 252;
    public static final int STATE_TYPE = 253;
    public static final int INJECTED_TYPE = 254;
    public static final int HELD_BACK_TYPE = 255;

    /** The hold's state stream (one per bus: one spy per session). */
    public static final StreamKey STATE = new StreamKey("stagecraft", "robot-hold", STATE_TYPE, 0, 0, 0);

    /** The session's simulated world frozen or thawed ({@link WorldChange}; one per bus). */
    public static final StreamKey WORLD = new StreamKey("stagecraft", "world", WORLD_TYPE, 0, 0, 0);

    private HoldStreams() {
    }

    public static StreamKey actionKey(HoldAction a) {
        MessageHeader h = a.header();
        return switch (a.kind()) {
            case BREAK -> SpyStreams.key(a.connection(), Direction.SERVER_TO_CLIENT, BREAK_TYPE, h.interf(), h.index(), h.subtype());
            case PASSED_ON -> SpyStreams.key(a.connection(), Direction.SERVER_TO_CLIENT, PASSED_ON_TYPE, h.interf(), h.index(),
                    h.subtype());
            case INJECTED -> SpyStreams.key(a.connection(), Direction.CLIENT_TO_SERVER, INJECTED_TYPE, h.interf(), h.index(),
                    h.subtype());
            default -> SpyStreams.key(a.connection(), Direction.CLIENT_TO_SERVER, HELD_BACK_TYPE, h.interf(), h.index(),
                    h.subtype());
        };
    }

    /** Every zero command the holds injected, on every connection. */
    public static StreamPattern injected() {
        return StreamPattern.any().messageType(INJECTED_TYPE);
    }

    /** Every robot data breakpoint hit, on every connection. */
    public static StreamPattern breaks() {
        return StreamPattern.any().messageType(BREAK_TYPE);
    }

    /** Every program message the holds kept from Player, on every connection. */
    public static StreamPattern heldBack() {
        return StreamPattern.any().messageType(HELD_BACK_TYPE);
    }
}
