package org.stagecraft.mcap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The generic writer and reader: what is written is read back, through the summary and by scanning, past damage. */
class McapRoundTripTest {
    @TempDir
    Path tmp;

    private record Written(int channel, long logTime, long publishTime, byte[] data) {
    }

    /** Two schemas, three channels, metadata, {@code n} messages in chunks of {@code chunkSize}. */
    private static List<Written> write(Path file, int n, int chunkSize) throws IOException {
        List<Written> out = new ArrayList<>();
        Random random = new Random(42);
        try (McapWriter w = new McapWriter(FileChannel.open(file, StandardOpenOption.CREATE,
                StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE),
                new McapWriter.Options("", "stagecraft mcap test", chunkSize, 1))) {
            w.metadata("test.info", Map.of("a", "1", "b", "two"));
            int json = w.addSchema("test.Count", "jsonschema",
                    "{\"type\":\"object\"}".getBytes(StandardCharsets.UTF_8));
            assertEquals(json, w.addSchema("test.Count", "jsonschema",
                    "{\"type\":\"object\"}".getBytes(StandardCharsets.UTF_8)), "an identical schema is reused");
            int a = w.addChannel("/a", "json", json, Map.of("k", "v"));
            int b = w.addChannel("/b", "json", json, Map.of());
            int c = w.addChannel("/raw", "json", 0, Map.of());
            int unused = w.addChannel("/unused", "json", 0, Map.of());
            assertEquals(List.of(1, 2, 3, 4), List.of(a, b, c, unused), "ids count up from 1");
            for (int i = 0; i < n; i++) {
                int ch = i % 3 == 0 ? a : i % 3 == 1 ? b : c;
                byte[] data = ("{\"n\":" + i + ",\"pad\":\"" + "x".repeat(random.nextInt(200)) + "\"}")
                        .getBytes(StandardCharsets.UTF_8);
                long t = 1_700_000_000_000_000_000L + 1000L * i;
                w.message(ch, t, t - 7, data);
                out.add(new Written(ch, t, t - 7, data));
            }
        }
        return out;
    }

    private static List<Written> readAll(McapReader r) throws IOException {
        List<Written> got = new ArrayList<>();
        for (ChunkInfo c : r.chunks()) {
            try {
                r.readChunk(c, m -> got.add(new Written(m.channel(), m.logTime(), m.publishTime(), m.copyData())));
            } catch (McapFormatException damaged) {
                // listed in damage()
            }
        }
        return got;
    }

    private static void assertSame(List<Written> expected, List<Written> actual) {
        assertEquals(expected.size(), actual.size());
        for (int i = 0; i < expected.size(); i++) {
            Written e = expected.get(i);
            Written a = actual.get(i);
            assertEquals(e.channel(), a.channel(), "message " + i);
            assertEquals(e.logTime(), a.logTime(), "message " + i);
            assertEquals(e.publishTime(), a.publishTime(), "message " + i);
            assertArrayEquals(e.data(), a.data(), "message " + i);
        }
    }

    @Test
    void whatIsWrittenIsReadBackThroughTheSummaryWithoutReadingAChunk() throws IOException {
        Path logs = Files.createDirectories(Path.of("target", "test-logs"));
        Path file = logs.resolve("generic.mcap"); // checked by ./stagecraft test with MCAP's own tools
        List<Written> written = write(file, 5000, 16 * 1024);
        try (McapReader r = McapReader.open(file)) {
            assertTrue(r.complete());
            assertFalse(r.recovered());
            assertEquals("stagecraft mcap test", r.library());
            assertEquals(Map.of("a", "1", "b", "two"), r.metadata().get("test.info"));
            assertEquals(List.of("/a", "/b", "/raw"), r.channels().values().stream().map(Channel::topic).toList(),
                    "a channel without messages is not written");
            assertEquals(Map.of("k", "v"), r.channels().get(1).metadata());
            assertEquals("test.Count", r.schemas().get(1).name());
            assertEquals(1, r.schemas().size());
            assertTrue(r.chunks().size() > 10, r.chunks().size() + " chunks");
            assertEquals(Map.of(1, 1667L, 2, 1667L, 3, 1666L), r.messageCounts());
            assertEquals(written.get(0).logTime(), r.startTime());
            assertEquals(written.get(written.size() - 1).logTime(), r.endTime());
            assertSame(written, readAll(r));
            assertEquals(List.of(), r.damage());
        }
    }

    /** Offsets of the chunk records, walking the records from the start. */
    private static List<Integer> chunkOffsets(byte[] file) {
        List<Integer> out = new ArrayList<>();
        int p = 8;
        while (p + 9 <= file.length && file[p] != Mcap.OP_DATA_END) {
            if (file[p] == Mcap.OP_CHUNK) {
                out.add(p);
            }
            p += 9 + (int) ByteBuffer.wrap(file, p + 1, 8).order(ByteOrder.LITTLE_ENDIAN).getLong();
        }
        return out;
    }

    private List<Written> withoutChunk(List<Written> all, Path file, int chunk) throws IOException {
        long[] range = new long[2];
        try (McapReader r = McapReader.open(file)) {
            range[0] = r.chunks().get(chunk).startTime();
            range[1] = r.chunks().get(chunk).endTime();
        }
        return all.stream().filter(w -> w.logTime() < range[0] || w.logTime() > range[1]).toList();
    }

    @Test
    void aDamagedChunkInACompleteFileThrowsWhenReadAndIsListedWithItsLostMessages() throws IOException {
        Path file = tmp.resolve("damaged.mcap");
        List<Written> written = write(file, 5000, 8 * 1024);
        byte[] bytes = Files.readAllBytes(file);
        int at = chunkOffsets(bytes).get(10);
        Arrays.fill(bytes, at + 200, at + 264, (byte) 0);
        Files.write(file, bytes);
        List<Written> expected = withoutChunk(written, file, 10);
        try (McapReader r = McapReader.open(file)) {
            assertFalse(r.recovered(), "the summary is intact");
            ChunkInfo ten = r.chunks().get(10);
            McapFormatException e = assertThrows(McapFormatException.class, () -> r.readChunk(ten, m -> {
            }));
            assertTrue(e.getMessage().contains("chunk 10 at offset " + at), e.getMessage());
            assertSame(expected, readAll(r));
            assertEquals(1, r.damage().size(), "listed once: " + r.damage());
            Damage d = r.damage().get(0);
            assertEquals(at, d.offset());
            assertEquals(written.size() - expected.size(), d.messagesLost());
        }
    }

    @Test
    void withoutTheSummaryEveryIntactChunkIsRecoveredAroundDamagedOnes() throws IOException {
        Path file = tmp.resolve("scan.mcap");
        List<Written> written = write(file, 5000, 8 * 1024);
        byte[] original = Files.readAllBytes(file);
        List<Integer> chunks = chunkOffsets(original);
        int footerless = original.length - (9 + 20 + 8);
        // the first chunk's records, chunk 10's length (nothing after it lines up) and chunk 20's records
        byte[] bytes = Arrays.copyOf(original, footerless);
        Arrays.fill(bytes, chunks.get(0) + 100, chunks.get(0) + 164, (byte) 0);
        bytes[chunks.get(10) + 2] ^= 0x11;
        Arrays.fill(bytes, chunks.get(20) + 300, chunks.get(20) + 364, (byte) 0x55);
        Files.write(file, bytes);
        List<Written> expected = written;
        Path intact = tmp.resolve("intact.mcap");
        Files.write(intact, original);
        for (int k : new int[] { 0, 10, 20 }) {
            expected = withoutChunk(expected, intact, k);
        }
        try (McapReader r = McapReader.open(file)) {
            assertTrue(r.recovered());
            assertEquals(chunks.size() - 3, r.chunks().size());
            assertSame(expected, readAll(r));
            List<Damage> damage = r.damage();
            assertEquals(3, damage.size(), damage.toString());
            assertEquals(List.of((long) chunks.get(0), (long) chunks.get(10), (long) chunks.get(20)),
                    damage.stream().map(Damage::offset).toList());
            long lost = damage.stream().mapToLong(Damage::messagesLost).sum();
            assertEquals(written.size() - expected.size(), lost, damage.toString());
            assertEquals(3, r.channels().size(), "the definitions precede the chunks, outside them");
        }
    }

    @Test
    void aFileCutOffAnywhereKeepsEveryCompleteChunk() throws IOException {
        Path file = tmp.resolve("cut-source.mcap");
        List<Written> written = write(file, 2000, 4 * 1024);
        byte[] bytes = Files.readAllBytes(file);
        List<Integer> chunks = chunkOffsets(bytes);
        Random random = new Random(7);
        for (int k = 0; k < 60; k++) {
            int cut = 8 + random.nextInt(bytes.length - 8);
            Path part = Files.write(tmp.resolve("cut.mcap"), Arrays.copyOf(bytes, cut));
            try (McapReader r = McapReader.open(part)) {
                List<Written> got = readAll(r);
                int complete = (int) chunks.stream().filter(c -> c < cut).count();
                assertTrue(r.chunks().size() >= complete - 1 && r.chunks().size() <= complete, "cut at " + cut);
                assertSame(written.subList(0, got.size()), got);
                assertTrue(r.damage().stream().allMatch(Damage::cutOff) && r.damage().size() <= 1,
                        "cut at " + cut + ": " + r.damage());
            }
        }
    }

    @Test
    void notMcapIsRefusedByName() throws IOException {
        Path file = Files.writeString(tmp.resolve("x.mcap"), "{\"t\":1}\n");
        McapFormatException e = assertThrows(McapFormatException.class, () -> McapReader.open(file));
        assertTrue(e.getMessage().contains("x.mcap") && e.getMessage().contains("not an MCAP file"), e.getMessage());
    }
}
