package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 17 item 5: {@code decode} and {@code stats} on files that are not player-traces say which
 * file, which line and why, in one line without a stack trace, and exit 1.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class BadInputFilesTest {
    private static final String HEADER = "{\"format\":\"player-trace\",\"version\":1}\n";

    @TempDir
    Path tmp;


    private static CommandRun run(String... args) {
        return CommandRun.of(args);
    }

    private Path file(String name, byte[] content) throws IOException {
        Path p = tmp.resolve(name);
        Files.write(p, content);
        return p;
    }

    /** Exit 1 and exactly one line on stderr: "stagecraft COMMAND: FILE:LINE: REASON", no exception in sight. */
    private static void assertRefused(String command, CommandRun r, Path file, int line, String reason) {
        assertEquals(1, r.code(), r.err());
        String expected = "stagecraft " + command + ": " + file + ":" + line + ": ";
        assertTrue(r.err().startsWith(expected), "expected '" + expected + "...' but got: " + r.err());
        assertTrue(r.err().contains(reason), "expected the reason '" + reason + "' in: " + r.err());
        assertEquals(1, r.err().lines().count(), "one line: " + r.err());
        assertFalse(r.err().contains("Exception") || r.err().contains("\tat "), "no stack trace or exception name: " + r.err());
        assertFalse(r.err().contains("Input length"), r.err());
    }

    @ParameterizedTest
    @ValueSource(strings = { "decode", "stats" })
    void aHeaderVersionThatIsNotANumber(String command) throws IOException {
        Path f = file("version-x.trace.jsonl", "{\"format\":\"player-trace\",\"version\":\"x\"}\n".getBytes(StandardCharsets.UTF_8));
        assertRefused(command, run(command, f.toString()), f, 1, "unsupported player-trace version \"x\"");
    }

    @ParameterizedTest
    @ValueSource(strings = { "decode", "stats" })
    void binaryInput(String command) throws IOException {
        byte[] bytes = new byte[4096];
        new Random(17).nextBytes(bytes);
        bytes[0] = (byte) 0x89; // not the MCAP magic, not text
        Path f = file("random.bin", bytes);
        assertRefused(command, run(command, f.toString()), f, 1, "not UTF-8 text (byte 0x89)");
    }

    @ParameterizedTest
    @ValueSource(strings = { "decode", "stats" })
    void textThatIsNotUtf8(String command) throws IOException {
        byte[] latin1 = (HEADER + "{\"conn\":1,\"event\":\"open\",\"t\":0.5,\"port\":6665,\"note\":\"d\u00e9j\u00e0\"}\n")
                .getBytes(StandardCharsets.ISO_8859_1);
        Path f = file("latin1.trace.jsonl", latin1);
        assertRefused(command, run(command, f.toString()), f, 2, "not UTF-8 text (byte 0xe9)");
    }

    @ParameterizedTest
    @ValueSource(strings = { "decode", "stats" })
    void aLineOf64MiBInASmallHeapIsTooLongNotInvalidJson(String command) throws Exception {
        Path f = tmp.resolve("long-line.trace.jsonl");
        try (OutputStream out = Files.newOutputStream(f)) {
            out.write((HEADER + "{\"t\":1,\"conn\":1,\"port\":6665,\"dir\":\"c2s\",\"data\":\"").getBytes(StandardCharsets.US_ASCII));
            byte[] block = new byte[1 << 20];
            java.util.Arrays.fill(block, (byte) 'A');
            for (int i = 0; i < 64; i++) {
                out.write(block);
            }
            out.write("\"}\n".getBytes(StandardCharsets.US_ASCII));
        }
        // the tool in a JVM of its own with a small heap (64 MiB: the line alone would not fit twice)
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-Xmx64m", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                command, f.toString()).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertRefused(command, new CommandRun(p.exitValue(), "", err), f, 2, "line too long (more than 16 MiB");
        assertFalse(err.contains("not valid JSON"), err);
    }

    @ParameterizedTest
    @ValueSource(strings = { "decode", "stats" })
    void aTruncatedLastLine(String command) throws IOException {
        Path f = file("cut.trace.jsonl", (HEADER + "{\"conn\":1,\"event\":\"open\",\"t\":0.5,\"port\":66").getBytes(StandardCharsets.UTF_8));
        assertRefused(command, run(command, f.toString()), f, 2, "not valid JSON");
    }
}
