package org.stagecraft.recording.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

/**
 * Issue 17 item 5: files that are not player-traces (a bad header, binary data, text that is not
 * UTF-8, a line of 64 MiB) are refused with the file, the line and the reason — no
 * NumberFormatException, no "Input length = 1", and a long line is refused before it is read whole.
 */
class TraceReaderBadInputTest {
    private static final String NAME = "bad.trace.jsonl";
    private static final String HEADER = "{\"format\":\"player-trace\",\"version\":1}\n";

    private static String failure(byte[] file) {
        TraceFormatException e = assertThrows(TraceFormatException.class, () -> {
            try (TraceReader r = new TraceReader(NAME, new ByteArrayInputStream(file))) {
                while (r.next() != null) {
                    // to the end or the first problem
                }
            }
        });
        return e.getMessage();
    }

    private static String failure(String file) {
        return failure(file.getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void aVersionThatIsNotANumberIsNamed() {
        assertEquals(NAME + ":1: unsupported player-trace version \"x\" (this reader knows version 1)",
                failure("{\"format\":\"player-trace\",\"version\":\"x\"}\n"));
        assertEquals(NAME + ":1: unsupported player-trace version 2 (this reader knows version 1)",
                failure("{\"format\":\"player-trace\",\"version\":2}\n"));
        assertEquals(NAME + ":1: unsupported player-trace version [1] (this reader knows version 1)",
                failure("{\"format\":\"player-trace\",\"version\":[1]}\n"));
        assertEquals(NAME + ":1: unsupported player-trace version 1e999999999999 (this reader knows version 1)",
                failure("{\"format\":\"player-trace\",\"version\":1e999999999999}\n"));
        assertEquals(NAME + ":1: the header has no \"version\" (this reader knows player-trace version 1)",
                failure("{\"format\":\"player-trace\"}\n"));
    }

    @Test
    void versionOneWrittenAsOneOrOnePointZeroIsAccepted() throws IOException {
        for (String v : new String[] { "1", "1.0", "\"1\"" }) {
            String file = "{\"format\":\"player-trace\",\"version\":" + v + "}\n";
            try (TraceReader r = new TraceReader(NAME, new ByteArrayInputStream(file.getBytes(StandardCharsets.UTF_8)))) {
                assertInstanceOf(TraceRecord.Header.class, r.next(), v);
            }
        }
    }

    @Test
    void binaryInputNamesLineColumnAndByte() {
        byte[] png = { (byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13 };
        assertEquals(NAME + ":1: column 1: not UTF-8 text (byte 0x89); a player-trace is UTF-8 JSON lines", failure(png));

        ByteArrayOutputStream nul = new ByteArrayOutputStream();
        nul.writeBytes(HEADER.getBytes(StandardCharsets.US_ASCII));
        nul.writeBytes(new byte[] { '{', '"', 't', '"', ':', 0, '}', '\n' });
        assertEquals(NAME + ":2: column 6: binary data, not text (byte 0x00)", failure(nul.toByteArray()));
    }

    @Test
    void textThatIsNotUtf8NamesLineColumnAndByte() {
        // Latin-1 'é' (0xe9) inside a header field: valid JSON in Latin-1, not UTF-8
        byte[] latin1 = "{\"format\":\"player-trace\",\"version\":1,\"scenario\":\"caf\u00e9\"}\n"
                .getBytes(StandardCharsets.ISO_8859_1);
        assertEquals(NAME + ":1: column 53: not UTF-8 text (byte 0xe9); a player-trace is UTF-8 JSON lines",
                failure(latin1));
    }

    @Test
    void utf8TextIsRead() throws IOException {
        String file = "{\"format\":\"player-trace\",\"version\":1,\"scenario\":\"caf\u00e9 \u2192 \ud83e\udd16\"}\r\n";
        try (TraceReader r = new TraceReader(NAME, new ByteArrayInputStream(file.getBytes(StandardCharsets.UTF_8)))) {
            TraceRecord.Header h = assertInstanceOf(TraceRecord.Header.class, r.next());
            assertEquals("caf\u00e9 \u2192 \ud83e\udd16", h.fields().get("scenario"));
        }
    }

    @Test
    void aLineOf64MiBIsRefusedAsTooLongWithBoundedMemory() {
        long for64MiB = allocatedToRefuse(64L << 20);
        long for1GiB = allocatedToRefuse(1L << 30);
        // one line's buffer (it grows by doubling up to 16 MiB: about 32 MiB allocated in all), whatever
        // the line's length; reading the line whole would take several times its size
        assertTrue(for64MiB < 64L << 20, "allocated " + (for64MiB >> 20) + " MiB to refuse a 64 MiB line");
        assertTrue(for1GiB < 64L << 20, "allocated " + (for1GiB >> 20) + " MiB to refuse a 1 GiB line");
    }

    private static long allocatedToRefuse(long lineBytes) {
        InputStream file = new HugeLineTrace(HEADER, lineBytes);
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long before = threads.getCurrentThreadAllocatedBytes();
        TraceFormatException e = assertThrows(TraceFormatException.class, () -> {
            try (TraceReader r = new TraceReader(NAME, file)) {
                while (r.next() != null) {
                    // the header, then the long line
                }
            }
        });
        long allocated = threads.getCurrentThreadAllocatedBytes() - before;
        assertEquals(NAME + ":2: line too long (more than 16 MiB; a player-trace line holds one recv() of at most 16 MiB)",
                e.getMessage());
        return allocated;
    }

    @Test
    void aLineJustUnderTheLimitIsStillRead() throws IOException {
        int dataChars = TraceLines.MAX_LINE_BYTES - 100; // base64 of (dataChars / 4 * 3) zero bytes
        dataChars -= dataChars % 4;
        StringBuilder line = new StringBuilder(dataChars + 100).append(HEADER)
                .append("{\"t\":1,\"conn\":1,\"port\":6665,\"dir\":\"c2s\",\"data\":\"");
        line.repeat('A', dataChars).append("\"}\n");
        try (TraceReader r = new TraceReader(NAME, new ByteArrayInputStream(line.toString().getBytes(StandardCharsets.US_ASCII)))) {
            r.next();
            TraceRecord.Chunk c = assertInstanceOf(TraceRecord.Chunk.class, r.next());
            assertEquals(dataChars / 4 * 3, c.data().length);
        }
    }

    /** A header, then one valid chunk line of {@code lineBytes} (all base64 'A'), produced on the fly. */
    static final class HugeLineTrace extends InputStream {
        private final byte[] head;
        private final byte[] tail = "\"}\n".getBytes(StandardCharsets.US_ASCII);
        private final long total;
        private long pos;

        HugeLineTrace(String header, long lineBytes) {
            this.head = (header + "{\"t\":1,\"conn\":1,\"port\":6665,\"dir\":\"c2s\",\"data\":\"").getBytes(StandardCharsets.US_ASCII);
            this.total = header.length() + lineBytes;
        }

        @Override
        public int read() {
            byte[] one = new byte[1];
            return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
        }

        @Override
        public int read(byte[] b, int off, int len) {
            if (pos >= total) {
                return -1;
            }
            int n = (int) Math.min(len, total - pos);
            for (int i = 0; i < n; i++, pos++) {
                if (pos < head.length) {
                    b[off + i] = head[(int) pos];
                } else if (pos >= total - tail.length) {
                    b[off + i] = tail[(int) (pos - (total - tail.length))];
                } else {
                    b[off + i] = 'A';
                }
            }
            return n;
        }
    }
}
