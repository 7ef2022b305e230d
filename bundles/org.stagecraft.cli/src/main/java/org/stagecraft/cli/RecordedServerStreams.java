package org.stagecraft.cli;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.stagecraft.demo.recorded.TimedChunk;
import org.stagecraft.demo.recorded.TimedConnection;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;

/**
 * The connections of a session log as the recorded Player served them: per connection the
 * server-to-client bytes (banner, messages, unframed bytes) timed from the connection's open, and
 * what the client sent, for comparing.
 */
final class RecordedServerStreams {
    private RecordedServerStreams() {
    }

    private static final class Builder {
        final int conn;
        final int port;
        final long openedNanos;
        long endNanos;
        final List<TimedChunk> client = new ArrayList<>();
        final List<TimedChunk> server = new ArrayList<>();

        Builder(int conn, int port, long openedNanos) {
            this.conn = conn;
            this.port = port;
            this.openedNanos = openedNanos;
            this.endNanos = openedNanos;
        }
    }

    /** Every connection that carried anything from the server, in connection order. */
    static List<TimedConnection> read(SessionLog log) throws IOException {
        Map<Integer, Builder> byConn = new LinkedHashMap<>();
        try (LogCursor c = log.cursor(Long.MIN_VALUE)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                LogMessage first = m;
                Builder b = byConn.computeIfAbsent(m.connection().id(),
                        k -> new Builder(k, first.connection().port(), first.timeNanos()));
                b.endNanos = Math.max(b.endNanos, m.timeNanos());
                if (m.kind() == LogMessage.Kind.BANNER || m.kind() == LogMessage.Kind.FRAME
                        || m.kind() == LogMessage.Kind.UNFRAMED) {
                    TimedChunk chunk = new TimedChunk(Math.max(0, m.timeNanos() - b.openedNanos) / 1e9, m.bytes());
                    (m.dir() == Direction.SERVER_TO_CLIENT ? b.server : b.client).add(chunk);
                }
            }
        }
        List<TimedConnection> out = new ArrayList<>();
        for (Builder b : byConn.values()) {
            if (!b.server.isEmpty()) {
                out.add(new TimedConnection(b.conn, b.port, b.client, b.server, (b.endNanos - b.openedNanos) / 1e9));
            }
        }
        return out;
    }
}
