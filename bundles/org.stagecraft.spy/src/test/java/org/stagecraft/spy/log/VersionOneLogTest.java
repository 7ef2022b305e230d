package org.stagecraft.spy.log;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.mcap.McapWriter;
import org.stagecraft.mcap.RecordBuffer;
import org.stagecraft.player.wire.Direction;

/**
 * Logs written before version 2 of the layout (docs/spy-log.md, "Logs written before version 2") stay
 * readable. The file is made here with the generic writer in the old layout, byte for byte as the
 * old writer laid out its messages: x-player-xdr wire channels with a schema of empty encoding, the
 * x-stagecraft-hold channel at id 65535 (here: the last id), profile x-stagecraft-spy.
 */
class VersionOneLogTest {
    @TempDir
    Path tmp;

    private static void oldWire(McapWriter w, int channel, long t, long offset, int kind, String reason, byte[] bytes)
            throws IOException {
        synchronized (w) {
            byte[] why = reason.getBytes(StandardCharsets.UTF_8);
            RecordBuffer b = w.beginMessage(channel, t, t);
            b.u64(offset).u8(kind).u16(why.length).bytes(why).bytes(bytes);
            w.endMessage();
        }
    }

    private static void oldHold(McapWriter w, int channel, long t, int conn, int port, int action, long programOffset,
            long upstreamOffset, String text, byte[] bytes) throws IOException {
        synchronized (w) {
            byte[] why = text.getBytes(StandardCharsets.UTF_8);
            RecordBuffer b = w.beginMessage(channel, t, t);
            b.u32(conn).u32(port).u8(action).u64(programOffset).u64(upstreamOffset).u16(why.length).bytes(why).bytes(bytes);
            w.endMessage();
        }
    }

    @Test
    void aVersionOneLogIsReadWithItsStreamsEventsAndHolds() throws IOException {
        Path log = tmp.resolve("v1.mcap");
        byte[] banner = new byte[32];
        byte[] frame = new byte[48];
        frame[39] = 8; // size field: 8 bytes of payload
        byte[] injected = new byte[40];
        try (McapWriter w = new McapWriter(FileChannel.open(log, StandardOpenOption.CREATE, StandardOpenOption.WRITE),
                new McapWriter.Options("x-stagecraft-spy", "stagecraft spy log 1", 1 << 20, 1))) {
            w.metadata("stagecraft.session", Map.of("host", "old"));
            int events = w.addChannel("/events", "json",
                    w.addSchema("stagecraft.SpyEvent", "jsonschema", "{}".getBytes(StandardCharsets.UTF_8)), Map.of());
            int wireSchema = w.addSchema("player.Message", "", new byte[0]);
            int c2s = w.addChannel("/wire/1/6665/c2s", "x-player-xdr", wireSchema,
                    Map.of("conn", "1", "port", "6665", "dir", "c2s", "client", "127.0.0.1:5000"));
            int s2c = w.addChannel("/wire/1/6665/s2c", "x-player-xdr", wireSchema, Map.of("conn", "1", "port", "6665", "dir", "s2c", "client", "127.0.0.1:5000"));
            int hold = w.addChannel("/stagecraft/hold", "x-stagecraft-hold",
                    w.addSchema("stagecraft.Hold", "", new byte[0]), Map.of("stagecraft", "hold"));
            w.message(events, 10, 10, ("{\"event\":\"opened\",\"conn\":1,\"client\":\"127.0.0.1:5000\","
                    + "\"listen\":\"0.0.0.0:6665\",\"upstream\":\"localhost:7665\"}").getBytes(StandardCharsets.UTF_8));
            oldWire(w, s2c, 11, 0, 1, "", banner);
            oldWire(w, c2s, 12, 0, 2, "", frame);
            oldHold(w, hold, 13, 1, 6665, 1, 48, 48, "zero velocity", injected);
            oldWire(w, c2s, 14, 48, 3, "garbage", new byte[] { 1, 2, 3 });
            w.message(events, 15, 15, "{\"event\":\"closed\",\"conn\":1,\"reason\":\"bye\"}".getBytes(StandardCharsets.UTF_8));
        }
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertFalse(r.recovered());
            assertEquals(Map.of("host", "old"), r.metadata());
            assertEquals(3, r.messageCount());
            assertEquals(2, r.eventCount());
            List<LogEntry> entries = new ArrayList<>();
            for (Iterator<LogEntry> it = r.entries(); it.hasNext();) {
                entries.add(it.next());
            }
            assertEquals(5, entries.size(), entries.toString());
            LogEntry.Wire unframed = (LogEntry.Wire) entries.get(3);
            assertEquals(LogEntry.Kind.UNFRAMED, unframed.kind());
            assertEquals("garbage", unframed.reason());
            assertEquals(48, unframed.streamOffset());
            assertEquals(14, unframed.captureNanos());
            byte[] program = r.programBytes(1);
            assertEquals(51, program.length);
            assertArrayEquals(banner, r.streamBytes(1, Direction.SERVER_TO_CLIENT));
            List<HoldEntry> holds = r.holdEntries();
            assertEquals(1, holds.size());
            assertEquals(HoldEntry.Action.INJECTED, holds.get(0).action());
            assertEquals("zero velocity", holds.get(0).text());
            assertEquals(51 + 40, r.upstreamBytes(1).length);
            assertEquals(1, r.connections().size());
            assertEquals("bye", r.connections().get(0).closeReason());
            assertEquals(List.of("127.0.0.1:5000"), r.indexedConnections().stream().map(LogConnection::client).toList());
        }
    }
}
