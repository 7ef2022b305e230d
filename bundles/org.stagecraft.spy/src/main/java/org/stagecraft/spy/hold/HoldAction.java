package org.stagecraft.spy.hold;

import java.util.List;

import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * One thing a hold did to a connection: a whole Player message it injected (a zero-velocity command), a
 * whole message of the program's it held back, or a robot data breakpoint's hit on a message from Player
 * and the passing on of what it held back from the program. Published on the stream bus
 * ({@link HoldStreams}) and logged ({@link HoldEntry}).
 *
 * @param kind           {@link HoldEntry.Action#INJECTED}, {@link HoldEntry.Action#HELD_BACK},
 *                       {@link HoldEntry.Action#BREAK} or {@link HoldEntry.Action#PASSED_ON}
 * @param programOffset  offset in the program's stream: injected before the program's byte there;
 *                       held-back bytes start there
 * @param upstreamOffset offset in the stream Player receives
 * @param header         the message's header
 * @param bytes          the exact message bytes (header and payload)
 * @param text           for people, e.g. "zero velocity to position2d:0 (suspended in the debugger)"
 * @param decidingFields for a {@link HoldEntry.Action#BREAK}, the message's fields that decided the breakpoint
 *                       ({@code ranges[147]}), for a view to mark; empty otherwise. Not in the log: a
 *                       replayed break marks the whole triggering reading.
 */
public record HoldAction(ConnectionInfo connection, HoldEntry.Action kind, long programOffset, long upstreamOffset,
        MessageHeader header, byte[] bytes, String text, List<String> decidingFields) {

    public HoldAction {
        bytes = bytes.clone();
        decidingFields = List.copyOf(decidingFields);
    }

    public HoldAction(ConnectionInfo connection, HoldEntry.Action kind, long programOffset, long upstreamOffset,
            MessageHeader header, byte[] bytes, String text) {
        this(connection, kind, programOffset, upstreamOffset, header, bytes, text, List.of());
    }

    @Override
    public byte[] bytes() {
        return bytes.clone();
    }

    public int length() {
        return bytes.length;
    }

    /** The log's record of it. */
    public HoldEntry toEntry(long timeNanos) {
        return new HoldEntry(timeNanos, connection.id(), connection.port(), kind, programOffset, upstreamOffset, bytes,
                text);
    }
}
