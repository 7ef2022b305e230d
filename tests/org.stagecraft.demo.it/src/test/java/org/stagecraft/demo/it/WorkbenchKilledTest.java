package org.stagecraft.demo.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.junit.jupiter.api.Test;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The tools a session starts do not outlive the workbench even when it cannot run its shutdown code:
 * the demo's product is killed with SIGKILL while its Robot Session runs (the recorded Player and the
 * recorded robot program are processes of their own), and afterwards none of the processes the
 * workbench had started is left and Player's port is free again.
 */
class WorkbenchKilledTest {
    private static final int PLAYER_PORT = 6665;

    @Test
    void noToolOutlivesAWorkbenchKilledWithSigkill() throws Exception {
        Path dir = Files.createDirectories(Path.of("target", "demo-it-killed").toAbsolutePath());
        Path workspace = dir.resolve("workspace-" + System.nanoTime());
        Path status = dir.resolve("status.json");
        Files.deleteIfExists(status);
        Path out = dir.resolve("output.txt");
        ProcessBuilder pb = new ProcessBuilder(DemoRun.root().resolve("stagecraft").toString(), "demo", "--exit-after",
                "600", "--player", "recorded", "--status", status.toString()).directory(DemoRun.root().toFile())
                .redirectErrorStream(true).redirectOutput(out.toFile());
        pb.environment().put("STAGECRAFT_DEMO_WORKSPACE", workspace.toString());
        pb.environment().remove("STAGECRAFT_DEMO_PLAYER");
        Process script = pb.start();
        List<ProcessHandle> started = new ArrayList<>();
        try {
            awaitSessionRunning(status, out, script);
            ProcessHandle workbench = script.descendants()
                    .filter(h -> h.info().commandLine().orElse("").contains("org.eclipse.equinox.launcher"))
                    .findFirst().orElseThrow(() -> new AssertionError("no workbench JVM among the demo's processes"));
            workbench.descendants().forEach(started::add);
            assertTrue(started.stream().anyMatch(h -> h.info().commandLine().orElse("").contains("RecordedPlayerMain")),
                    "the session's Player runs as a process of the workbench: " + describe(started));

            assertTrue(workbench.destroyForcibly(), "SIGKILL sent to the workbench");
            workbench.onExit().get(30, TimeUnit.SECONDS);

            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            for (ProcessHandle h : started) {
                long remaining = deadline - System.nanoTime();
                if (remaining > 0) {
                    try {
                        h.onExit().get(remaining, TimeUnit.NANOSECONDS);
                    } catch (TimeoutException e) {
                        // still running at the deadline: reported below
                    }
                }
            }
            List<ProcessHandle> left = started.stream().filter(ProcessHandle::isAlive).toList();
            assertEquals(List.of(), left, "processes the killed workbench had started are still running: " + describe(left));
            assertFalse(listening(PLAYER_PORT), "port " + PLAYER_PORT + " is free again");
        } finally {
            script.descendants().forEach(ProcessHandle::destroyForcibly);
            started.forEach(ProcessHandle::destroyForcibly);
            script.destroyForcibly();
            script.waitFor(30, TimeUnit.SECONDS);
        }
    }

    /** Until the demo's status says the session runs with Player ready (or the script ends: a failure). */
    private static void awaitSessionRunning(Path status, Path out, Process script) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(420); // may build the product first
        while (System.nanoTime() < deadline) {
            if (!script.isAlive()) {
                fail("the demo ended before its session ran; output:\n" + Files.readString(out));
            }
            Optional<JsonObject> s = read(status);
            if (s.isPresent() && "running".equals(s.get().get("phase").getAsString()) && playerReady(s.get())) {
                return;
            }
            script.onExit().completeOnTimeout(script, 200, TimeUnit.MILLISECONDS).get();
        }
        fail("the demo's session did not run within the time limit; output:\n" + Files.readString(out));
    }

    private static boolean playerReady(JsonObject s) {
        if (!s.has("tools")) {
            return false;
        }
        for (JsonElement e : s.getAsJsonArray("tools")) {
            JsonObject t = e.getAsJsonObject();
            if ("Player".equals(t.get("part").getAsString()) && "READY".equals(t.get("state").getAsString())) {
                return true;
            }
        }
        return false;
    }

    private static Optional<JsonObject> read(Path status) {
        try {
            return Files.exists(status) ? Optional.of(JsonParser.parseString(Files.readString(status)).getAsJsonObject())
                    : Optional.empty();
        } catch (IOException | RuntimeException e) {
            return Optional.empty(); // being rewritten: read it again
        }
    }

    private static String describe(List<ProcessHandle> handles) {
        return handles.stream().map(h -> h.pid() + " " + h.info().commandLine().orElse("?")).toList().toString();
    }

    private static boolean listening(int port) throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            return true;
        } catch (ConnectException e) {
            return false;
        }
    }
}
