package org.stagecraft.recording.peers;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/**
 * Both byte streams of one recorded connection, each kept as the chunks the recorder's recv()
 * returned, so a peer can send them with the original segmentation.
 *
 * @param conn the connection number in the trace
 * @param port the port the recorded client connected to
 */
public record RecordedConnection(int conn, int port, List<byte[]> clientChunks, List<byte[]> serverChunks) {

    public RecordedConnection {
        clientChunks = List.copyOf(clientChunks);
        serverChunks = List.copyOf(serverChunks);
    }

    /** Everything the client sent, in order. */
    public byte[] clientBytes() {
        return concat(clientChunks);
    }

    /** Everything the server sent (ident banner first), in order. */
    public byte[] serverBytes() {
        return concat(serverChunks);
    }

    public byte[] bytes(Direction dir) {
        return dir == Direction.CLIENT_TO_SERVER ? clientBytes() : serverBytes();
    }

    /** Every connection of a trace file, in accept order. */
    public static List<RecordedConnection> read(Path trace) throws IOException {
        Map<Integer, int[]> ports = new LinkedHashMap<>();
        Map<Integer, List<byte[]>> c2s = new LinkedHashMap<>();
        Map<Integer, List<byte[]>> s2c = new LinkedHashMap<>();
        try (TraceReader r = new TraceReader(trace)) {
            for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                if (rec instanceof TraceRecord.Chunk c) {
                    int conn = c.stream().conn();
                    ports.putIfAbsent(conn, new int[] {c.stream().port()});
                    c2s.computeIfAbsent(conn, k -> new ArrayList<>());
                    s2c.computeIfAbsent(conn, k -> new ArrayList<>());
                    (c.stream().dir() == Direction.CLIENT_TO_SERVER ? c2s : s2c).get(conn).add(c.data());
                } else if (rec instanceof TraceRecord.Lifecycle l) {
                    ports.putIfAbsent(l.conn(), new int[] {l.port()});
                    c2s.computeIfAbsent(l.conn(), k -> new ArrayList<>());
                    s2c.computeIfAbsent(l.conn(), k -> new ArrayList<>());
                }
            }
        }
        List<RecordedConnection> out = new ArrayList<>();
        for (Map.Entry<Integer, int[]> e : ports.entrySet()) {
            int conn = e.getKey();
            out.add(new RecordedConnection(conn, e.getValue()[0], c2s.get(conn), s2c.get(conn)));
        }
        return out;
    }

    private static byte[] concat(List<byte[]> chunks) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] c : chunks) {
            out.writeBytes(c);
        }
        return out.toByteArray();
    }
}
