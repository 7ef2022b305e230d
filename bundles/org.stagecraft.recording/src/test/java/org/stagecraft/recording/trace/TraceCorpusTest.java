package org.stagecraft.recording.trace;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.codec.RawBody;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.session.StreamId;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;

/** Every shared recording of real Player/Stage traffic, framed, decoded and re-encoded. */
class TraceCorpusTest {
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());

    static List<Path> traces() {
        return TraceCorpus.all();
    }

    private static List<SessionEvent> frame(Path trace) throws IOException {
        List<SessionEvent> events = new ArrayList<>();
        TraceFraming.frame(trace, events::add);
        return events;
    }

    /** The concatenated recv() bytes of each stream, as recorded. */
    private static Map<StreamId, byte[]> streams(Path trace) throws IOException {
        Map<StreamId, ByteArrayOutputStream> out = new LinkedHashMap<>();
        try (TraceReader r = new TraceReader(trace)) {
            for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                if (rec instanceof TraceRecord.Chunk c) {
                    out.computeIfAbsent(c.stream(), k -> new ByteArrayOutputStream()).writeBytes(c.data());
                }
            }
        }
        Map<StreamId, byte[]> result = new LinkedHashMap<>();
        out.forEach((k, v) -> result.put(k, v.toByteArray()));
        return result;
    }

    @ParameterizedTest
    @MethodSource("traces")
    void framesCompletelyWithoutErrors(Path trace) throws IOException {
        List<SessionEvent> events = frame(trace);
        long frames = 0;
        for (SessionEvent e : events) {
            if (e.event() instanceof WireEvent.Unframed u) {
                fail(trace.getFileName() + ": " + e.stream() + " offset " + u.offset() + ": " + u.reason());
            }
            if (e.event() instanceof WireEvent.Frame) {
                frames++;
            }
        }
        assertTrue(frames > 100, "a real session has many messages: " + frames);
        Map<StreamId, byte[]> recorded = streams(trace);
        for (Map.Entry<StreamId, byte[]> s : recorded.entrySet()) {
            ByteArrayOutputStream covered = new ByteArrayOutputStream();
            events.stream().filter(e -> e.stream().equals(s.getKey())).forEach(e -> covered.writeBytes(e.event().bytes()));
            assertArrayEquals(s.getValue(), covered.toByteArray(), s.getKey() + ": framed bytes must be exactly the stream");
        }
    }

    @ParameterizedTest
    @MethodSource("traces")
    void everyMessageDecodesToATypedBodyAndEncodesBackByteForByte(Path trace) throws IOException {
        int checked = 0;
        for (SessionEvent e : frame(trace)) {
            if (e.event() instanceof WireEvent.Frame f) {
                DecodedMessage m = DECODER.decode(f);
                assertFalse(m.hasProblem(), () -> trace.getFileName() + " " + e.stream() + " @" + f.offset() + ": "
                        + m.problem().reason());
                assertFalse(m.body() instanceof RawBody, () -> "no decoder for " + f.header());
                byte[] again = PlayerEncoder.encode(m);
                if (!Arrays.equals(f.bytes(), again)) {
                    fail(trace.getFileName() + " " + e.stream() + " @" + f.offset() + " " + f.header()
                            + " does not re-encode identically");
                }
                checked++;
            }
        }
        assertTrue(checked > 100);
    }

    @ParameterizedTest
    @MethodSource("traces")
    void framingIsTheSameByteByByteAndUnderRandomChunking(Path trace) throws IOException {
        Random random = new Random(trace.getFileName().toString().hashCode());
        for (Map.Entry<StreamId, byte[]> s : streams(trace).entrySet()) {
            byte[] bytes = s.getValue();
            List<String> reference = summary(s.getKey(), bytes, new int[] {bytes.length});
            int[] oneByOne = new int[bytes.length];
            Arrays.fill(oneByOne, 1);
            assertEquals(reference, summary(s.getKey(), bytes, oneByOne), s.getKey() + " byte by byte");
            for (int round = 0; round < 3; round++) {
                List<Integer> sizes = new ArrayList<>();
                for (int left = bytes.length; left > 0;) {
                    int n = Math.min(left, 1 + random.nextInt(random.nextBoolean() ? 7 : 3000));
                    sizes.add(n);
                    left -= n;
                }
                assertEquals(reference, summary(s.getKey(), bytes, sizes.stream().mapToInt(i -> i).toArray()),
                        s.getKey() + " random chunks, round " + round);
            }
        }
    }

    private static List<String> summary(StreamId stream, byte[] bytes, int[] chunkSizes) {
        List<String> out = new ArrayList<>();
        PlayerFramer framer = new PlayerFramer(stream.dir(), e -> out.add(e.getClass().getSimpleName() + "@" + e.offset()
                + "#" + Arrays.hashCode(e.bytes())));
        int at = 0;
        for (int n : chunkSizes) {
            framer.accept(bytes, at, n);
            at += n;
        }
        framer.end();
        return out;
    }
}
