package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Base64;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.wire.PlayerFramer;

/**
 * Issue 17 item 7, scaled down: {@code decode} of a trace whose 100 000 connections never close, each
 * left with half a message header, in a 32 MiB heap (it needs 20 MiB). The state kept per connection
 * is one small object plus the held header bytes (main ran out of memory in 48 MiB here: a framer with
 * its buffers per direction). The million-connection case and the launcher's default heap are measured in
 * docs/robustness.md.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class NeverClosedConnectionsTest {
    private static final int CONNECTIONS = 100_000;

    @TempDir
    Path tmp;

    @Test
    void decodeOfAHundredThousandOpenConnectionsFitsInASmallHeap() throws Exception {
        Path trace = tmp.resolve("never-closed.trace.jsonl");
        String banner = Base64.getEncoder().encodeToString(Arrays.copyOf("Player v.3.1.1-dev".getBytes(StandardCharsets.US_ASCII),
                PlayerFramer.IDENT_LENGTH));
        String halfHeader = Base64.getEncoder().encodeToString(new byte[20]);
        try (BufferedWriter w = Files.newBufferedWriter(trace)) {
            w.write("{\"format\":\"player-trace\",\"version\":1,\"scenario\":\"never-closed\"}\n");
            for (int c = 1; c <= CONNECTIONS; c++) {
                w.write("{\"conn\":" + c + ",\"event\":\"open\",\"t\":1,\"port\":6665}\n");
                w.write("{\"t\":1,\"conn\":" + c + ",\"port\":6665,\"dir\":\"s2c\",\"data\":\"" + banner + "\"}\n");
                w.write("{\"t\":1,\"conn\":" + c + ",\"port\":6665,\"dir\":\"c2s\",\"data\":\"" + halfHeader + "\"}\n");
            }
        }
        Path out = tmp.resolve("decoded.jsonl");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-Xmx32m", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "decode", trace.toString()).redirectOutput(out.toFile()).start();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(100, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), err);
        try (var lines = Files.lines(out)) {
            // a banner per connection, and at the end the half header of each, reported as unframed
            assertEquals(2L * CONNECTIONS, lines.count());
        }
        try (var lines = Files.lines(out)) {
            assertEquals(CONNECTIONS, lines.filter(l -> l.contains("\"error\":\"stream ended inside a message header")).count());
        }
    }
}
