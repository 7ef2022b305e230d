package org.stagecraft.spy.log;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Channels another tool adds beside the spy's own (decoded JSON for Foxglove): the spy's reader
 * skips them and still reads every wire entry and event exactly; a log written the same way without
 * them is byte for byte the same as it would be without the feature.
 */
class AddedChannelsTest {

    @Test
    void spyReaderSkipsAddedChannelsAndReadsEverythingElse(@TempDir Path dir) throws IOException {
        Path trace = TraceLogs.all().get(0);
        Path plain = dir.resolve("plain.mcap");
        TraceLogs.Expected x = TraceLogs.writeFile(trace, plain, Map.of("k", "v"));

        Path logs = Files.createDirectories(Path.of("target", "test-logs"));
        Path added = logs.resolve("added-channels.mcap");
        byte[] schema = "{\"type\":\"object\",\"properties\":{\"n\":{\"type\":\"integer\"}}}".getBytes(StandardCharsets.UTF_8);
        try (SpyLogWriter w = SpyLogWriter.create(added, Map.of("k", "v"))) {
            int a = w.addChannel("/count", "json", "test.Count", "jsonschema", schema, Map.of("what", "a count"));
            int b = w.addChannel("/other", "json", "test.Count", "jsonschema", schema, Map.of());
            TraceLogs.write(trace, w);
            for (int i = 0; i < 5000; i++) {
                w.message(i % 2 == 0 ? a : b, 1_000_000L * i, ("{\"n\":" + i + "}").getBytes(StandardCharsets.UTF_8));
            }
            assertThrows(IllegalArgumentException.class, () -> w.message(1, 0, new byte[0]), "the events channel is the spy's");
            assertThrows(IllegalArgumentException.class, () -> w.message(b + 1, 0, new byte[0]),
                    "a wire channel (the first one after the added channels) is the spy's");
        }
        assertEquals(x.wire.size(), entries(added).stream().filter(e -> e instanceof LogEntry.Wire).count());
        List<LogEntry> p = entries(plain);
        List<LogEntry> q = entries(added);
        assertEquals(p.size(), q.size());
        for (int i = 0; i < p.size(); i++) {
            if (p.get(i) instanceof LogEntry.Wire pw) {
                LogEntry.Wire qw = (LogEntry.Wire) q.get(i);
                assertArrayEquals(pw.bytes(), qw.bytes());
                assertEquals(pw.timeNanos(), qw.timeNanos());
                assertEquals(pw.conn(), qw.conn());
                assertEquals(pw.streamOffset(), qw.streamOffset());
            } else {
                assertEquals(p.get(i), q.get(i));
            }
        }
        try (SpyLogReader r = SpyLogReader.open(added); SpyLogReader s = SpyLogReader.open(plain)) {
            assertEquals(s.messageCount(), r.messageCount());
            assertEquals(s.eventCount(), r.eventCount());
            assertEquals(s.connections(), r.connections());
        }
    }

    @Test
    void messageRefusesEveryChannelAddChannelDidNotReturnBeforeAndAfterAnyWasAdded(@TempDir Path dir) throws IOException {
        byte[] json = "{}".getBytes(StandardCharsets.UTF_8);
        try (SpyLogWriter w = SpyLogWriter.create(dir.resolve("guard.mcap"), Map.of())) {
            w.connectionOpened(0, 1, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");
            w.wire(1, 1, 6665, org.stagecraft.player.wire.Direction.SERVER_TO_CLIENT, 0, LogEntry.Kind.BANNER,
                    "Player v.3.1.1".getBytes(StandardCharsets.UTF_8), "");
            int wireChannel = 2; // /events is 1, the first wire channel 2
            for (int channel : new int[] { 1, wireChannel, 0xffff, 0, 12345 }) {
                assertThrows(IllegalArgumentException.class, () -> w.message(channel, 2, json),
                        "channel " + channel + " before any addChannel");
            }
            int added = w.addChannel("/n", "json", "test.N", "jsonschema", "{}".getBytes(StandardCharsets.UTF_8), Map.of());
            w.message(added, 3, json);
            for (int channel : new int[] { 1, wireChannel, added - 1, 0, 12345 }) {
                assertThrows(IllegalArgumentException.class, () -> w.message(channel, 4, json),
                        "channel " + channel + " after addChannel returned " + added);
            }
        }
    }

    private static List<LogEntry> entries(Path log) throws IOException {
        List<LogEntry> out = new ArrayList<>();
        try (SpyLogReader r = SpyLogReader.open(log)) {
            for (Iterator<LogEntry> it = r.entries(); it.hasNext();) {
                out.add(it.next());
            }
        }
        return out;
    }
}
