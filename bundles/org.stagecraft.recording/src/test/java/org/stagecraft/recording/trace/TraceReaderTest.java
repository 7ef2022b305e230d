package org.stagecraft.recording.trace;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.wire.Direction;

class TraceReaderTest {
    private static final String HEADER = "{\"format\":\"player-trace\",\"version\":1,\"scenario\":\"x\"}\n";

    private static TraceReader reader(String text) {
        return reader(text.getBytes(StandardCharsets.UTF_8));
    }

    private static TraceReader reader(byte[] bytes) {
        return new TraceReader("test.trace.jsonl", new ByteArrayInputStream(bytes));
    }

    @Test
    void readsHeaderChunksAndLifecycle() throws IOException {
        try (TraceReader r = reader(HEADER + "{\"conn\":1,\"event\":\"open\",\"t\":0.5,\"port\":6665}\n"
                + "{\"t\":1.25,\"conn\":1,\"port\":6665,\"dir\":\"s2c\",\"data\":\"AAEC\"}\n\n"
                + "{\"conn\":1,\"event\":\"close\",\"t\":2,\"port\":6665}\n")) {
            TraceRecord.Header h = assertInstanceOf(TraceRecord.Header.class, r.next());
            assertEquals("x", h.fields().get("scenario"));
            TraceRecord.Lifecycle open = assertInstanceOf(TraceRecord.Lifecycle.class, r.next());
            assertEquals("open", open.event());
            TraceRecord.Chunk c = assertInstanceOf(TraceRecord.Chunk.class, r.next());
            assertEquals(1.25, c.t());
            assertEquals(Direction.SERVER_TO_CLIENT, c.stream().dir());
            assertArrayEquals(new byte[] {0, 1, 2}, c.data());
            assertTrue(assertInstanceOf(TraceRecord.Lifecycle.class, r.next()).isClose());
            assertNull(r.next());
        }
    }

    @Test
    void badInputNamesFileAndLine() {
        assertMessage(HEADER + "{\"t\":1,\"conn\":1,\"port\":6665,\"dir\":\"up\",\"data\":\"\"}\n",
                "test.trace.jsonl:2: unknown direction 'up'");
        assertMessage(HEADER + "{\"t\":1,\"conn\":1,\"port\":6665,\"dir\":\"c2s\",\"data\":\"!!\"}\n",
                "test.trace.jsonl:2: \"data\" is not base64");
        assertMessage(HEADER + "{\"t\":1,\"conn\":1,\"dir\":\"c2s\",\"data\":\"\"}\n", "test.trace.jsonl:2: missing \"port\"");
        assertMessage(HEADER + "{not json\n", "test.trace.jsonl:2: not valid JSON");
        assertMessage("{\"format\":\"something-else\"}\n", "test.trace.jsonl:1: expected a header");
        assertMessage("", "test.trace.jsonl: empty file");
        assertMessage("[1,2]\n", "test.trace.jsonl:1: expected a JSON object");
    }

    private static void assertMessage(String text, String expectedStart) {
        TraceFormatException e = assertThrows(TraceFormatException.class, () -> {
            try (TraceReader r = reader(text)) {
                while (r.next() != null) {
                    // read to the end
                }
            }
        });
        assertTrue(e.getMessage().startsWith(expectedStart), e.getMessage());
    }
}
