package org.stagecraft.demo.it;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * {@code ./stagecraft demo} run headless for a bounded time on the built product (under Xvfb, which
 * {@code ./stagecraft test} provides): the Robot Views drew, again and again, and drew data; the spy
 * log grew while the session ran; the recorded robot program and the recorded Player each got exactly
 * the other's recorded bytes through the spy; everything is gone afterwards. And a corrupt recording
 * ends the demo at once with a message that names the file and line.
 */
class StagecraftDemoTest {
    /** Long enough for one whole pass of the 30.4 s recording after the workbench and session start. */
    private static final int DEMO_SECONDS = 50;
    private static final byte[] MCAP_MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
    private static final int PLAYER_PORT = 6665;

    private static Path target;

    @BeforeAll
    static void dirs() throws IOException {
        target = Files.createDirectories(Path.of("target", "demo-it").toAbsolutePath());
    }

    private static Path fresh(String name) throws IOException {
        Path p = target.resolve(name);
        if (Files.exists(p)) {
            try (var walk = Files.walk(p)) {
                for (Path f : walk.sorted((a, b) -> b.getNameCount() - a.getNameCount()).toList()) {
                    Files.delete(f);
                }
            }
        }
        return p;
    }

    @Test
    void theDemoDrawsTheRecordedSessionLiveAndTheSpyLogGrows() throws Exception {
        assertPortFree("before the demo");
        Path workspace = fresh("workspace");
        Path status = target.resolve("status.json");
        Files.deleteIfExists(status);
        DemoRun run = DemoRun.run(workspace, status, DEMO_SECONDS + 240, "--exit-after", String.valueOf(DEMO_SECONDS),
                "--player", "recorded");
        String out = run.output();
        assertEquals(0, run.exitCode(), out);
        assertNotNull(run.status(), "the demo wrote its status; output:\n" + out);
        JsonObject s = run.status();
        assertEquals("finished", s.get("phase").getAsString(), s + "\n" + out);
        assertTrue(s.get("recordedPlayer").getAsBoolean());
        assertTrue(out.contains("stagecraft demo: closing the workbench after " + DEMO_SECONDS + " s"), out);

        // the project was created from what the product ships
        Path project = workspace.resolve("pioneer-demo");
        assertTrue(Files.isRegularFile(project.resolve("worlds/pioneer-laser-sonar.cfg")));
        assertTrue(Files.isRegularFile(project.resolve("worlds/bitmaps/cave.png")));
        assertEquals(2295378, Files.size(project.resolve("recordings/pioneer-laser-sonar.gt.trace.jsonl")));

        // the views drew, and kept drawing: frames went up over the last ten seconds
        JsonArray samples = s.getAsJsonArray("samples");
        assertTrue(samples.size() >= 20, "a sample a second: " + samples.size());
        JsonObject last = samples.get(samples.size() - 1).getAsJsonObject();
        JsonObject tenBefore = samples.get(samples.size() - 11).getAsJsonObject();
        long[] framesNow = longs(last.getAsJsonArray("frames"));
        long[] framesThen = longs(tenBefore.getAsJsonArray("frames"));
        assertEquals(2, framesNow.length, "two Robot Views");
        for (int v = 0; v < 2; v++) {
            assertTrue(framesNow[v] > framesThen[v] + 50, "Robot View " + v + " is animated: " + framesThen[v] + " -> "
                    + framesNow[v] + " frames in 10 s");
        }
        // ... and what they drew is data: laser, sonar and robot are the only colours in a frame
        JsonArray views = s.getAsJsonArray("views");
        for (JsonElement e : views) {
            JsonObject v = e.getAsJsonObject();
            int pixels = v.get("width").getAsInt() * v.get("height").getAsInt();
            int coloured = v.get("colouredPixels").getAsInt();
            assertTrue(coloured > pixels / 100, v.get("id") + " drew sensor data: " + coloured + " of " + pixels + " pixels");
        }

        // the spy log grew while the session ran, in many steps
        List<Long> sizes = new ArrayList<>();
        for (JsonElement e : samples) {
            sizes.add(e.getAsJsonObject().get("spyLogBytes").getAsLong());
        }
        long first = sizes.get(0), end = sizes.get(sizes.size() - 1);
        long rises = 0;
        for (int i = 1; i < sizes.size(); i++) {
            assertTrue(sizes.get(i) >= sizes.get(i - 1), "the log never shrinks: " + sizes);
            rises += sizes.get(i) > sizes.get(i - 1) ? 1 : 0;
        }
        assertTrue(end > first + 300_000 && rises >= 15, "the spy log grew steadily: " + sizes);
        Path log = Path.of(s.get("spyLog").getAsString());
        assertTrue(log.startsWith(project.resolve("spy-logs")), log.toString());
        assertTrue(Files.size(log) >= end, "the log on disk holds at least what was sampled");
        try (InputStream in = Files.newInputStream(log)) {
            assertArrayEquals(MCAP_MAGIC, in.readNBytes(MCAP_MAGIC.length), "an MCAP file");
        }

        // the whole pipeline ran: every part up, and each recorded peer got the other's exact bytes
        for (String part : List.of("Recorded robot program", "Player", "Network Spy")) {
            assertTrue(s.getAsJsonArray("tools").asList().stream().map(JsonElement::getAsJsonObject)
                    .anyMatch(t -> t.get("part").getAsString().equals(part) && t.get("state").getAsString().equals("READY")),
                    part + " was running: " + s.get("tools"));
        }
        List<String> reports = s.getAsJsonArray("reports").asList().stream().map(JsonElement::getAsString).toList();
        assertTrue(reports.stream().anyMatch(l -> l.startsWith("Recorded robot program: recorded robot: pass 1 ")
                && l.endsWith("exactly what the recorded Player sent")), "robot pass 1 through the spy: " + reports);
        assertTrue(reports.stream().anyMatch(l -> l.startsWith("Player: recorded Player: served recorded connection 1 ")
                && l.endsWith("exactly what the recorded robot program sent")), "Player's side through the spy: " + reports);
        String editor = s.get("sessionLogEditor").getAsString();
        assertEquals("opened", editor, "the live spy log opened in the Session Log editor");

        assertPortFree("after the demo: the session was stopped with the workbench");
    }

    @Test
    void aCorruptRecordingEndsTheDemoAtOnceWithFileAndLine() throws Exception {
        Path workspace = fresh("workspace-corrupt");
        Path status = target.resolve("status-corrupt.json");
        Files.deleteIfExists(status);
        Path bad = Files.writeString(target.resolve("cut.trace.jsonl"),
                "{\"format\":\"player-trace\",\"version\":1}\n{\"t\":0.1,\"conn\":1,\"port\":6665,\"dir\":\"s2c\",\"da");
        int limit = 120;
        DemoRun run = DemoRun.run(workspace, status, limit + 240, "--exit-after", String.valueOf(limit), "--recording",
                bad.toString());
        assertEquals(0, run.exitCode(), run.output());
        assertTrue(run.seconds() < limit, "closed at once, not after " + limit + " s: " + run.seconds());
        String message = "the demo recording cannot be used: the recording is corrupt: " + bad + ":2: not valid JSON";
        assertTrue(run.output().contains("stagecraft demo: ERROR " + message), run.output());
        assertEquals("failed", run.status().get("phase").getAsString());
        assertTrue(run.status().get("error").getAsString().startsWith(message), run.status().toString());
        assertPortFree("nothing was started");
    }

    @Test
    void aMissingRecordingIsNamedBeforeAnythingStarts() throws Exception {
        Path workspace = fresh("workspace-missing");
        Path missing = target.resolve("no-such.trace.jsonl");
        DemoRun run = DemoRun.run(workspace, null, 60, "--exit-after", "5", "--recording", missing.toString());
        assertEquals(1, run.exitCode(), run.output());
        assertTrue(run.output().contains("stagecraft: the recording " + missing + " does not exist"), run.output());
        assertTrue(Files.notExists(workspace.resolve(".metadata")), "the product was not started");
    }

    private static long[] longs(JsonArray a) {
        return a.asList().stream().mapToLong(JsonElement::getAsLong).toArray();
    }

    private static void assertPortFree(String when) throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), PLAYER_PORT)) {
            throw new AssertionError(when + ": something listens on " + PLAYER_PORT + " (" + s + ")");
        } catch (ConnectException expected) {
            // refused: free
        }
    }

}
