package org.stagecraft.replay.log;

import java.util.Arrays;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.MessageHeader;
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
