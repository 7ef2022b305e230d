package org.stagecraft.cli;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.play.ChunkSource;
import org.stagecraft.recording.play.PlayableConnection;
import org.stagecraft.recording.play.TimedChunk;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;

/**
 * The connections of a session log as the recorded Player served them, read from the log while
 * they are served: a 1 GB spy log is servable because only each connection's place in the log is
 * kept (number, port, first and last time), and each side's bytes are streamed through a cursor of
 * the open log as the replay reaches them.
 */
final class RecordedServerStreams {
    private RecordedServerStreams() {
    }

    /** Where one recorded connection is in the log; its bytes stay there. */
    record LogConnection(SessionLog log, int conn, int port, long openedNanos, long endNanos) implements PlayableConnection {
        @Override
        public double length() {
            return (endNanos - openedNanos) / 1e9;
        }

        @Override
        public ChunkSource openServer() throws IOException {
            return new WireChunks(this, Direction.SERVER_TO_CLIENT);
        }

        @Override
        public ChunkSource openClient() throws IOException {
            return new WireChunks(this, Direction.CLIENT_TO_SERVER);
        }
    }

    /**
     * One direction of one connection: its banner, Player messages and unframed pieces, in log order,
     * each timed from the connection's open. The cursor reads the chunks around its position only.
     */
    private static final class WireChunks implements ChunkSource {
        private final LogConnection c;
        private final Direction dir;
        private final LogCursor cursor;

        WireChunks(LogConnection c, Direction dir) throws IOException {
            this.c = c;
            this.dir = dir;
            this.cursor = c.log().cursor(c.openedNanos());
        }

        @Override
        public @Nullable TimedChunk next() throws IOException {
            for (LogMessage m = cursor.next(); m != null && m.timeNanos() <= c.endNanos(); m = cursor.next()) {
                if (m.connection().id() == c.conn() && m.dir() == dir && isWire(m)) {
                    return new TimedChunk(Math.max(0, m.timeNanos() - c.openedNanos()) / 1e9, m.bytes());
                }
            }
            return null;
        }

        @Override
        public void close() throws IOException {
            cursor.close();
        }
    }

    private static boolean isWire(LogMessage m) {
        return m.kind() == LogMessage.Kind.BANNER || m.kind() == LogMessage.Kind.FRAME || m.kind() == LogMessage.Kind.UNFRAMED;
    }

    private static final class Extent {
        final int port;
        final long openedNanos;
        long endNanos;
        boolean serverSent;

        Extent(int port, long openedNanos) {
            this.port = port;
            this.openedNanos = openedNanos;
            this.endNanos = openedNanos;
        }
    }

    /**
     * Every connection that carried anything from the server, in connection order. One pass over
     * the log notes each connection's extent; nothing of its traffic is kept. The log must stay open
     * while the connections are served.
     */
    static List<LogConnection> read(SessionLog log) throws IOException {
        Map<Integer, Extent> byConn = new LinkedHashMap<>();
        try (LogCursor c = log.cursor(Long.MIN_VALUE)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                LogMessage first = m;
                Extent e = byConn.computeIfAbsent(m.connection().id(), k -> new Extent(first.connection().port(), first.timeNanos()));
                e.endNanos = Math.max(e.endNanos, m.timeNanos());
                e.serverSent |= isWire(m) && m.dir() == Direction.SERVER_TO_CLIENT;
            }
        }
        List<LogConnection> out = new ArrayList<>();
        for (Map.Entry<Integer, Extent> e : byConn.entrySet()) {
            Extent x = e.getValue();
            if (x.serverSent) {
                out.add(new LogConnection(log, e.getKey(), x.port, x.openedNanos, x.endNanos));
            }
        }
        return out;
    }
}
