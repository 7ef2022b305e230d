package org.stagecraft.replay.writelog;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.log.Logs;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;

/**
 * Every message of the shared traces that writelog can hold, written as writelog text and read back,
 * equals the original: the same header fields and the same payload bytes. The only messages allowed
 * to differ are those the writer itself reports as approximated, and for those nothing the text
 * holds may be lost (writing the re-read message gives the same line).
 */
class WritelogRoundTripTest {
    private static final CodecRegistry REGISTRY = CodecRegistry.standard();

    static Stream<Path> traces() {
        return TraceCorpus.all().stream();
    }

    @ParameterizedTest
    @MethodSource("traces")
    void everyExpressibleMessageReadsBackExactly(Path trace) throws IOException {
        StringWriter text = new StringWriter();
        List<DecodedMessage> written = new ArrayList<>();
        long frames = 0;
        WritelogWriter w;
        try (SessionLog log = SessionLogs.open(trace)) {
            w = new WritelogWriter(text, REGISTRY, "3.1.1-dev", trace.getFileName().toString());
            for (LogMessage m : Logs.all(log)) {
                if (m.kind() == LogMessage.Kind.FRAME) {
                    frames++;
                    if (w.write(m)) {
                        written.add(m.decoded());
                    }
                }
            }
        }
        WritelogWriter.Summary s = w.summary();
        assertEquals(frames, s.written() + s.duplicates() + s.skippedTotal(), "every message is written, a duplicate or skipped");
        assertEquals(written.size(), s.written());
        assertTrue(s.written() > 100, trace + ": only " + s.written() + " messages written");

        List<WritelogRecord> back = new ArrayList<>();
        try (WritelogReader r = new WritelogReader("export", new BufferedReader(new StringReader(text.toString())))) {
            for (WritelogRecord rec = r.next(); rec != null; rec = r.next()) {
                back.add(rec);
            }
            assertEquals(List.of(), r.problems());
            assertEquals("3.1.1-dev", r.playerVersion());
            assertEquals(WritelogReader.FILE_VERSION, r.fileVersion());
        }
        assertEquals(written.size(), back.size());
        int differing = 0;
        for (int i = 0; i < written.size(); i++) {
            MessageHeader h = written.get(i).header();
            WritelogRecord rec = back.get(i);
            String where = trace.getFileName() + " message " + i + " (line " + rec.line() + ")";
            assertEquals(Double.doubleToRawLongBits(h.timestamp()), Double.doubleToRawLongBits(rec.time()), where);
            assertEquals(h.hostUnsigned(), rec.host(), where);
            assertEquals(h.robotUnsigned(), rec.robot(), where);
            assertEquals(h.interf(), rec.interf(), where);
            assertEquals(h.index(), rec.index(), where);
            assertEquals(h.type(), rec.type(), where);
            assertEquals(h.subtype(), rec.subtype(), where);
            byte[] original = PlayerEncoder.encodeBody(written.get(i).body());
            byte[] reread = PlayerEncoder.encodeBody(rec.body());
            if (!java.util.Arrays.equals(original, reread)) {
                differing++;
                assertEquals(4, rec.type(), where + ": only geometry/config replies may be approximated");
                assertEquals(lineOf(h, written.get(i)), lineOf(h, new DecodedMessage(h, rec.body(), null)),
                        where + ": the re-read message must write the same text");
            }
        }
        assertEquals(s.approximated(), differing, "the writer's count of approximated messages");
        // the data (laser, position2d, ranger) must all be exact
        long data = written.stream().filter(d -> d.header().type() == 1).count();
        assertTrue(data > 100, trace + ": data messages written: " + data);
    }

    @ParameterizedTest
    @MethodSource("traces")
    void writingTheReadBackFileAgainGivesTheSameText(Path trace) throws IOException {
        StringWriter first = new StringWriter();
        try (SessionLog log = SessionLogs.open(trace)) {
            WritelogWriter w = new WritelogWriter(first, REGISTRY, "3.1.1-dev", "x");
            for (LogMessage m : Logs.all(log)) {
                w.write(m);
            }
        }
        StringWriter second = new StringWriter();
        WritelogWriter w2 = new WritelogWriter(second, REGISTRY, "3.1.1-dev", "x");
        try (WritelogReader r = new WritelogReader("first", new BufferedReader(new StringReader(first.toString())))) {
            for (WritelogRecord rec = r.next(); rec != null; rec = r.next()) {
                assertTrue(w2.write(rec.header(0), rec.body()), "line " + rec.line() + " written again");
            }
        }
        assertEquals(first.toString(), second.toString());
    }

    private static String lineOf(MessageHeader h, DecodedMessage m) throws IOException {
        StringWriter s = new StringWriter();
        WritelogWriter w = new WritelogWriter(s, REGISTRY, null, null);
        assertTrue(w.write(h, m.body()));
        String all = s.toString();
        return all.substring(all.lastIndexOf('\n', all.length() - 2) + 1);
    }

    @org.junit.jupiter.api.Test
    void floatsAreWrittenShortestAndReadBackThroughADoubleExactly() {
        java.util.Random rnd = new java.util.Random(7);
        for (int i = 0; i < 200_000; i++) {
            float f = Float.intBitsToFloat(rnd.nextInt());
            if (Float.isNaN(f)) {
                continue;
            }
            String s = NumberText.float32(f);
            // readlog: atof (a double), then a cast to float
            assertEquals(Float.floatToRawIntBits(f), Float.floatToRawIntBits((float) NumberText.parseDouble(s)), s);
            assertTrue(s.length() <= Float.toString(f).length() || s.equals(Double.toString(f)), s);
        }
        assertArrayEquals(new String[] { "0.1", "-2.5E-7", "Infinity" },
                new String[] { NumberText.float32(0.1f), NumberText.float32(-2.5e-7f), NumberText.float32(Float.POSITIVE_INFINITY) });
    }
}
