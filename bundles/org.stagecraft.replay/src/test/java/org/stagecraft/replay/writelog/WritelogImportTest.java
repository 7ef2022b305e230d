package org.stagecraft.replay.writelog;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.log.SpyLogWriter;

/** A writelog file becomes a spy log: a connection per robot, a banner, every readable line as a message. */
class WritelogImportTest {

    @Test
    void everyLineBecomesAServerMessageOnItsRobotsConnection(@TempDir Path dir) throws IOException {
        Path log = dir.resolve("two-robots.log");
        Files.writeString(log, """
                ## Player version 3.0.2\s
                ## File version 0.3.0\s
                10.0 16777343 6665 position2d 00 001 001 +01.000 +02.000 +0.500 +00.100 +00.000 +00.050 0
                10.1 16777343 6666 sonar 00 001 001 2 0.500 0.600\s
                10.2 16777343 6665 position2d 00 001 001 +01.100 +02.000 +0.500 +00.100 +00.000 +00.050 0
                not a line
                10.15 16777343 6666 sonar 00 001 001 2 0.700 0.800\s
                """);
        Path spy = dir.resolve("imported.mcap");
        List<LogProblem> problems;
        try (SpyLogWriter w = SpyLogWriter.create(spy, Map.of("source", "test"))) {
            problems = WritelogImport.convert(log, w);
        }
        assertEquals(1, problems.size());
        assertEquals("line 6", problems.get(0).where());

        List<WritelogRecord> records = new ArrayList<>();
        try (WritelogReader r = new WritelogReader(log)) {
            for (WritelogRecord rec = r.next(); rec != null; rec = r.next()) {
                records.add(rec);
            }
        }
        PlayerDecoder decoder = new PlayerDecoder(CodecRegistry.standard());
        try (SpyLogReader r = SpyLogReader.open(spy)) {
            List<LogConnection> conns = r.connections();
            assertEquals(2, conns.size());
            assertEquals("writelog", conns.get(0).client());
            assertEquals("writelog:6665", conns.get(0).listen());
            assertEquals("writelog:6666", conns.get(1).listen());
            assertEquals(6666, conns.get(1).port());
            assertTrue(conns.get(0).closed() && conns.get(1).closed());
            assertEquals(Math.round(10.0 * 1e9), conns.get(0).openedNanos());
            assertEquals(Math.round(10.2 * 1e9), conns.get(1).closedNanos(), "closed at the file's last time");

            List<LogEntry.Wire> wire = new ArrayList<>();
            for (Iterator<LogEntry> it = r.entries(); it.hasNext();) {
                if (it.next() instanceof LogEntry.Wire w) {
                    wire.add(w);
                }
            }
            assertEquals(2 + 4, wire.size(), "two banners and four messages");
            List<LogEntry.Wire> banners = wire.stream().filter(w -> w.kind() == LogEntry.Kind.BANNER).toList();
            assertEquals(2, banners.size());
            assertTrue(new String(banners.get(0).bytes(), 0, 15).startsWith("Player v.3.0.2"));
            for (LogEntry.Wire w : wire) {
                assertEquals(Direction.SERVER_TO_CLIENT, w.dir());
            }
            List<LogEntry.Wire> frames = wire.stream().filter(w -> w.kind() == LogEntry.Kind.FRAME).toList();
            for (WritelogRecord rec : records) {
                LogEntry.Wire match = frames.stream().filter(f -> MessageHeader.read(f.bytes(), 0).timestamp() == rec.time())
                        .findFirst().orElseThrow();
                MessageHeader h = MessageHeader.read(match.bytes(), 0);
                assertEquals(rec.robot(), h.robotUnsigned());
                assertEquals(rec.interf(), h.interf());
                assertEquals(match.bytes().length - MessageHeader.SIZE, h.size());
                assertEquals(0, h.seq(), "a writelog line has no seq; Player sends 0");
                byte[] payload = java.util.Arrays.copyOfRange(match.bytes(), MessageHeader.SIZE, match.bytes().length);
                assertArrayEquals(PlayerEncoder.encodeBody(rec.body()), payload);
                assertEquals(rec.body(), decoder.decode(h, payload).body());
            }
            // a line earlier than the file's previous line (another robot's) keeps its own time as its
            // capture time; its log time does not go back (MCAP readers expect that)
            LogEntry.Wire late = frames.stream().filter(f -> MessageHeader.read(f.bytes(), 0).timestamp() == 10.15)
                    .findFirst().orElseThrow();
            assertEquals(Math.round(10.15 * 1e9), late.captureNanos());
            assertEquals(Math.round(10.2 * 1e9), late.timeNanos());
        }
    }
}
