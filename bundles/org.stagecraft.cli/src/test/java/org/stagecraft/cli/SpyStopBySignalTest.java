package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * {@code stagecraft spy} in a JVM of its own, stopped the way users stop it: SIGTERM (a service
 * manager, kill) or SIGINT (Ctrl-C). A clean stop closes the log and exits 0, not 143 or 130.
 */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SpyStopBySignalTest {
    @TempDir
    Path tmp;

    @ParameterizedTest
    @ValueSource(strings = {"TERM", "INT"})
    void aCleanStopOnASignalExitsZeroWithTheLogClosed(String signal) throws Exception {
        Path log = tmp.resolve("signal-" + signal + ".mcap");
        Process spy;
        try (ServerSocket player = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            spy = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), Main.class.getName(), "spy",
                    "--listen", "0", "--to", "127.0.0.1:" + player.getLocalPort(), "--log", log.toString())
                    .redirectErrorStream(true).start();
            List<String> lines = new ArrayList<>();
            try (BufferedReader out = new BufferedReader(new InputStreamReader(spy.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = out.readLine()) != null && !line.startsWith("logging to ")) {
                    lines.add(line); // the log is open once this line is out
                }
                assertTrue(line != null, "the spy ended before it was logging: " + lines);
                Process kill = new ProcessBuilder("kill", "-" + signal, String.valueOf(spy.pid())).inheritIO().start();
                assertEquals(0, kill.waitFor());
                while ((line = out.readLine()) != null) {
                    lines.add(line);
                }
            }
            assertTrue(spy.waitFor(60, TimeUnit.SECONDS), "the spy stops on SIG" + signal);
            assertEquals(0, spy.exitValue(), "a clean stop on SIG" + signal + " is a success: " + lines);
            assertTrue(lines.stream().anyMatch(l -> l.startsWith("stopped: 0 connections")), lines.toString());
        }
        assertTrue(Files.size(log) > 0);
        try (SpyLogReader r = SpyLogReader.open(log)) {
            assertFalse(r.recovered(), "the log was closed properly before the exit");
        }
    }
}
