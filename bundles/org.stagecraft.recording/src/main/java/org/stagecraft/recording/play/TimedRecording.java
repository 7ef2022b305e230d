package org.stagecraft.recording.play;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.trace.TraceFormatException;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/**
 * A recorded Player session (a player-trace file) read whole, with each connection's chunks timed
 * from that connection's open. Reading checks the whole file first: a replay that stopped half-way
 * because line 9000 is cut off would look like a bug in the replay, so a corrupt file is refused with
 * its file and line before anything is served.
 */
public record TimedRecording(Path file, List<TimedConnection> connections) {

    public TimedRecording {
        connections = List.copyOf(connections);
    }

    public static TimedRecording read(Path file) throws RecordingException {
        if (!Files.exists(file)) {
            throw new RecordingException("the recording " + file + " does not exist", new NoSuchFileException(file.toString()));
        }
        Map<Integer, Builder> byConn = new LinkedHashMap<>();
        try (TraceReader r = new TraceReader(file)) {
            for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                if (rec instanceof TraceRecord.Lifecycle l) {
                    Builder b = byConn.computeIfAbsent(l.conn(), c -> new Builder(c, l.port(), l.t()));
                    if (l.isClose()) {
                        b.closedAt = l.t();
                    }
                } else if (rec instanceof TraceRecord.Chunk c) {
                    Builder b = byConn.computeIfAbsent(c.stream().conn(), k -> new Builder(k, c.stream().port(), c.t()));
                    TimedChunk chunk = new TimedChunk(Math.max(0, c.t() - b.openedAt), c.data());
                    (c.stream().dir() == Direction.CLIENT_TO_SERVER ? b.client : b.server).add(chunk);
                    b.lastAt = Math.max(b.lastAt, c.t());
                }
            }
        } catch (TraceFormatException e) {
            throw new RecordingException("the recording is corrupt: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new RecordingException("cannot read the recording " + file + ": " + e.getMessage(), e);
        }
        List<TimedConnection> out = new ArrayList<>();
        for (Builder b : byConn.values()) {
            if (!b.server.isEmpty()) {
                out.add(b.build());
            }
        }
        if (out.isEmpty()) {
            throw new RecordingException("the recording " + file + " holds no connection in which Player sent anything", null);
        }
        return new TimedRecording(file, out);
    }

    private static final class Builder {
        final int conn, port;
        final double openedAt;
        double lastAt, closedAt = Double.NaN;
        final List<TimedChunk> client = new ArrayList<>(), server = new ArrayList<>();

        Builder(int conn, int port, double openedAt) {
            this.conn = conn;
            this.port = port;
            this.openedAt = openedAt;
            this.lastAt = openedAt;
        }

        TimedConnection build() {
            double end = Double.isNaN(closedAt) ? lastAt : Math.max(closedAt, lastAt);
            return new TimedConnection(conn, port, client, server, end - openedAt);
        }
    }
}
