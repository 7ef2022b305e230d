package org.stagecraft.recording.play;

import java.io.ByteArrayOutputStream;
import java.util.List;

/**
 * One recorded connection with the timing of its chunks, so that it can be played at the pace it
 * happened (unlike {@code RecordedConnection}, which keeps only the order).
 *
 * @param conn   the connection number in the recording
 * @param port   the port the recorded client connected to
 * @param client what the robot program sent, offsets from the connection's open
 * @param server what Player sent (the ident banner first)
 * @param length seconds from open to close (or to the last chunk when the close was not recorded)
 */
public record TimedConnection(int conn, int port, List<TimedChunk> client, List<TimedChunk> server, double length)
        implements PlayableConnection {

    public TimedConnection {
        client = List.copyOf(client);
        server = List.copyOf(server);
    }

    @Override
    public ChunkSource openServer() {
        return ChunkSource.of(server);
    }

    @Override
    public ChunkSource openClient() {
        return ChunkSource.of(client);
    }

    public byte[] clientBytes() {
        return concat(client);
    }

    public byte[] serverBytes() {
        return concat(server);
    }

    private static byte[] concat(List<TimedChunk> chunks) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (TimedChunk c : chunks) {
            out.writeBytes(c.data());
        }
        return out.toByteArray();
    }
}
