package org.stagecraft.replay.log;

import java.util.Arrays;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * Turns spy log entries into {@link LogMessage}s: decodes frames with the same decoder the live spy
 * uses, so a replayed message is the message the spy published.
 */
final class EntryConverter {
    private final PlayerDecoder decoder;
    private final Map<Integer, ConnectionInfo> connections;

    EntryConverter(CodecRegistry codecs, Map<Integer, ConnectionInfo> connections) {
        this.decoder = new PlayerDecoder(codecs);
        this.connections = connections;
    }

    ConnectionInfo connection(int conn, int port) {
        @Nullable ConnectionInfo c = connections.get(conn);
        // a recovered log may have lost the open event: name the connection by what is left
        return c != null ? c : named(conn, port, "", "", "");
    }

    /**
     * A connection with the addresses the log has for it; one whose open event was lost (a damaged or
     * cut-off log) or carried none is named by what is left, without spaces, for the names are stream
     * addresses on the bus and in exports.
     */
    static ConnectionInfo named(int conn, int port, @Nullable String client, @Nullable String listen,
            @Nullable String upstream) {
        return new ConnectionInfo(conn, port, client == null || client.isEmpty() ? "connection-" + conn : client,
                listen == null || listen.isEmpty() ? "port-" + port : listen, upstream == null ? "" : upstream);
    }

    /** A connection that carried no bytes is not among the indexed ones: its open event names it. */
    private ConnectionInfo opened(LogEntry.Opened o) {
        @Nullable ConnectionInfo c = connections.get(o.conn());
        return c != null ? c : new ConnectionInfo(o.conn(), -1, o.client(), o.listen(), o.upstream());
    }

    LogMessage convert(LogEntry e) {
        return switch (e) {
            case LogEntry.Opened o -> new LogMessage(o.timeNanos(), opened(o), null, -1, LogMessage.Kind.OPENED, new byte[0],
                    null, "");
            case LogEntry.Closed c -> new LogMessage(c.timeNanos(), connection(c.conn(), -1), null, -1,
                    LogMessage.Kind.CLOSED, new byte[0], null, c.reason());
            case LogEntry.Diagnostic d -> new LogMessage(d.timeNanos(), connection(d.conn(), -1), d.dir(),
                    d.streamOffset(), LogMessage.Kind.DIAGNOSTIC, new byte[0], null, d.text());
            case LogEntry.Wire w -> wire(w);
        };
    }

    /** What the robot hold or a data breakpoint did, as a row among the messages (see {@link LogMessage.Kind#HOLD}). */
    LogMessage hold(HoldEntry h) {
        ConnectionInfo c = h.conn() == 0 ? SESSION : connection(h.conn(), h.port());
        Direction dir = switch (h.action()) {
            case INJECTED, HELD_BACK -> Direction.CLIENT_TO_SERVER;
            case BREAK, PASSED_ON -> Direction.SERVER_TO_CLIENT;
            default -> null;
        };
        byte[] bytes = h.bytes();
        DecodedMessage d = null;
        if (bytes.length >= MessageHeader.SIZE) {
            MessageHeader header = MessageHeader.read(bytes, 0);
            if (header.size() == bytes.length - MessageHeader.SIZE) { // one whole message (held-back bytes may be several)
                d = decoder.decode(header, Arrays.copyOfRange(bytes, MessageHeader.SIZE, bytes.length));
            }
        }
        return new LogMessage(h.timeNanos(), c, dir, h.programOffset(), LogMessage.Kind.HOLD, bytes, d,
                HOLD_LABELS.get(h.action()) + h.text());
    }

    /** Rows of the session as a whole (hold on and off, the world frozen and thawed) belong to no connection. */
    static final ConnectionInfo SESSION = new ConnectionInfo(0, 0, "session", "robot hold", "");

    private static final Map<HoldEntry.Action, String> HOLD_LABELS = Map.of(
            HoldEntry.Action.INJECTED, "injected by Stagecraft: ",
            HoldEntry.Action.HELD_BACK, "held back from Player: ",
            HoldEntry.Action.HOLD_ON, "robots held: ",
            HoldEntry.Action.HOLD_OFF, "robots released: ",
            HoldEntry.Action.BREAK, "",
            HoldEntry.Action.PASSED_ON, "passed on to the program: ",
            HoldEntry.Action.WORLD_FROZEN, "world frozen: ",
            HoldEntry.Action.WORLD_THAWED, "world runs on: ");

    private LogMessage wire(LogEntry.Wire w) {
        ConnectionInfo c = connection(w.conn(), w.port());
        byte[] bytes = w.bytes();
        return switch (w.kind()) {
            case BANNER -> new LogMessage(w.timeNanos(), c, w.dir(), w.streamOffset(), LogMessage.Kind.BANNER, bytes,
                    null, "");
            case UNFRAMED -> new LogMessage(w.timeNanos(), c, w.dir(), w.streamOffset(), LogMessage.Kind.UNFRAMED,
                    bytes, null, w.reason());
            case FRAME -> {
                if (bytes.length < MessageHeader.SIZE) {
                    yield new LogMessage(w.timeNanos(), c, w.dir(), w.streamOffset(), LogMessage.Kind.UNFRAMED, bytes,
                            null, "logged as a message but shorter than a Player header");
                }
                DecodedMessage d = decoder.decode(MessageHeader.read(bytes, 0),
                        Arrays.copyOfRange(bytes, MessageHeader.SIZE, bytes.length));
                yield new LogMessage(w.timeNanos(), c, w.dir(), w.streamOffset(), LogMessage.Kind.FRAME, bytes, d,
                        d.hasProblem() ? "payload byte " + d.problem().payloadOffset() + ": " + d.problem().reason() : "");
            }
        };
    }
}
