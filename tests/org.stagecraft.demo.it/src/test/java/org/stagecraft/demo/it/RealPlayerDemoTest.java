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
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * {@code ./stagecraft demo --player PREFIX/bin/player} with the real Player/Stage that
 * {@code ./stagecraft player-stage install} built: the Robot Session runs that Player with Stage's
 * window (under the script's Xvfb) and Sunday Stroll as its robot program, which drives the robot
 * around the cave for the whole run. Checked from outside, as a user would: the status, the spy log
 * (decoded with {@code ./stagecraft decode}), Player's console, and that nothing is left running.
 *
 * <p>Part of the real-Player tier: only built with {@code -Dstagecraft.playerStage=PREFIX} (this
 * module's profile {@code real-player}, which {@code releng/tools/player-stage.sh tier} activates); without
 * an install it fails rather than skips.
 */
class RealPlayerDemoTest {
    private static final int DEMO_SECONDS = 60;
    /** The cave of the demo world is 16 m x 16 m around the origin. */
    private static final double CAVE_HALF = 8.0;

    @Test
    void sundayStrollDrivesTheRealPlayersRobotAroundTheCaveForTheWholeDemo() throws Exception {
        Path prefix = prefix();
        Path player = prefix.resolve("bin/player");
        Path target = Files.createDirectories(Path.of("target", "demo-it-real").toAbsolutePath());
        Path workspace = target.resolve("workspace");
        Path status = target.resolve("status.json");
        Files.deleteIfExists(status);
        assertPortFree("before the demo");

        // the Player named, nothing sourced: the session must give it its install's variables itself
        DemoRun run = DemoRun.run(workspace, status, DEMO_SECONDS + 300, "--exit-after", String.valueOf(DEMO_SECONDS),
                "--player", player.toString());
        String out = run.output();
        assertEquals(0, run.exitCode(), out);
        JsonObject s = run.status();
        assertTrue(s != null, "the demo wrote its status; output:\n" + out);
        assertEquals("finished", s.get("phase").getAsString(), s + "\n" + out);
        assertFalse(s.get("recordedPlayer").getAsBoolean(), s.toString());
        assertEquals(player.toString(), s.get("player").getAsString());
        assertEquals("programs/sunday_stroll.py", s.get("robotProgram").getAsString());

        // Player, the spy and the session ran to the end; Sunday Stroll ran, on the demo's Python, until the session stopped
        long playerPid = -1;
        for (String part : List.of("Player", "Network Spy", "Session")) {
            JsonObject row = s.getAsJsonArray("tools").asList().stream().map(JsonElement::getAsJsonObject)
                    .filter(t -> t.get("part").getAsString().equals(part)).findFirst()
                    .orElseThrow(() -> new AssertionError("no " + part + " in " + s.get("tools")));
            assertEquals("READY", row.get("state").getAsString(), part + " at the end: " + s.get("tools"));
            if (part.equals("Player")) {
                playerPid = row.get("pid").getAsLong();
            }
        }
        JsonObject stroll = s.getAsJsonArray("processes").asList().stream().map(JsonElement::getAsJsonObject)
                .filter(p -> p.get("label").getAsString().startsWith("sunday_stroll.py")).findFirst()
                .orElseThrow(() -> new AssertionError("Sunday Stroll is a process of the session: " + s.get("processes")));
        assertTrue(stroll.get("label").getAsString().contains("demo-venv"), "run by the demo's Python with pint: " + stroll);
        assertFalse(stroll.get("terminated").getAsBoolean(), "Sunday Stroll was still strolling at the end: " + stroll);

        // Player's console: it started Stage's plugin and said nothing about an error
        List<String> console = s.getAsJsonArray("playerConsole").asList().stream().map(JsonElement::getAsString).toList();
        assertTrue(console.stream().anyMatch(l -> l.contains("Stage driver setup")), "Player's console: " + console);
        assertFalse(console.stream().anyMatch(l -> l.toLowerCase().contains("error")), "no error from Player: " + console);

        // the spy log: the robot's poses, as Player sent them to Sunday Stroll
        Path log = Path.of(s.get("spyLog").getAsString());
        List<double[]> poses = poses(log);
        assertTrue(poses.size() > 200, "position2d data all along (about 10 a second): " + poses.size());
        double travelled = 0, lastThird = 0, start = poses.get(0)[0], end = poses.get(poses.size() - 1)[0];
        for (int i = 1; i < poses.size(); i++) {
            double[] a = poses.get(i - 1), b = poses.get(i);
            double d = Math.hypot(b[1] - a[1], b[2] - a[2]);
            travelled += d;
            if (b[0] > end - (end - start) / 3) {
                lastThird += d;
            }
        }
        for (double[] p : poses) {
            assertTrue(Math.abs(p[1]) < CAVE_HALF && Math.abs(p[2]) < CAVE_HALF,
                    "the robot stays inside the cave: (" + p[1] + ", " + p[2] + ")");
        }
        assertTrue(end - start > DEMO_SECONDS / 2.0, "poses over most of the run: " + (end - start) + " s");
        assertTrue(travelled > 1.0, "the robot travelled more than 1 m: " + travelled + " m");
        assertTrue(lastThird > 0.2, "and was still strolling in the last third of the run: " + lastThird + " m");

        // nothing left: Player's process and the port
        long pid = playerPid;
        assertTrue(pid > 0, "Player's pid in the status");
        assertFalse(ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false), "Player (pid " + pid + ") is gone");
        assertPortFree("after the demo");
    }

    @Test
    void playerKilledUnderTheDemoFailsTheSessionAndTheDemoAtOnce() throws Exception {
        Path player = prefix().resolve("bin/player");
        Path target = Files.createDirectories(Path.of("target", "demo-it-real").toAbsolutePath());
        Path workspace = target.resolve("workspace-killed");
        Path status = target.resolve("status-killed.json");
        Files.deleteIfExists(status);
        int limit = 240;
        DemoRun.Started started = DemoRun.start(workspace, status, "--exit-after", String.valueOf(limit), "--player",
                player.toString());
        // wait (polling the status the demo rewrites every second) until the session runs and Player has a pid
        long pid = -1;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(180);
        while (pid <= 0 && System.nanoTime() < deadline && started.process().isAlive()) {
            pid = playerPid(status);
            if (pid <= 0) {
                Thread.sleep(200); // polling interval, not synchronisation: the loop waits for the state itself
            }
        }
        assertTrue(pid > 0, "the demo's session ran with a Player pid in the status: "
                + (Files.exists(status) ? Files.readString(status) : "no status"));
        long killedAt = System.nanoTime();
        ProcessHandle handle = ProcessHandle.of(pid).orElseThrow(() -> new AssertionError("Player is not running"));
        assertTrue(handle.info().command().orElse("").endsWith("/bin/player"), "the pid is Player's: " + handle.info());
        Process kill = new ProcessBuilder("kill", "-9", String.valueOf(pid)).inheritIO().start();
        assertEquals(0, kill.waitFor(), "kill -9 " + pid);

        DemoRun run = started.await(limit + 120);
        double afterKill = (System.nanoTime() - killedAt) / 1e9;
        assertEquals(0, run.exitCode(), run.output());
        assertTrue(afterKill < 60, "the demo ended soon after Player was killed, not at --exit-after: " + afterKill + " s");
        JsonObject s = run.status();
        assertEquals("failed", s.get("phase").getAsString(), s.toString());
        String error = s.get("error").getAsString();
        assertTrue(error.startsWith("the Robot Session 'Pioneer demo' failed: Player is gone")
                && error.contains("signal 9"), error);
        assertTrue(run.output().contains("stagecraft demo: ERROR " + error), run.output());
        // the Tools view's rows, as the status took them after the failure
        for (String part : List.of("Player", "Session")) {
            assertTrue(s.getAsJsonArray("tools").asList().stream().map(JsonElement::getAsJsonObject)
                    .anyMatch(t -> t.get("part").getAsString().equals(part) && t.get("state").getAsString().equals("FAILED")),
                    part + " FAILED in the Tools view: " + s.get("tools"));
        }
        assertPortFree("after the failed demo");
    }

    private static long playerPid(Path status) {
        try {
            JsonObject s = JsonParser.parseString(Files.readString(status)).getAsJsonObject();
            if (!s.has("tools") || !"running".equals(s.get("phase").getAsString())) {
                return -1;
            }
            return s.getAsJsonArray("tools").asList().stream().map(JsonElement::getAsJsonObject)
                    .filter(t -> t.get("part").getAsString().equals("Player") && t.has("pid")
                            && t.get("state").getAsString().equals("READY"))
                    .mapToLong(t -> t.get("pid").getAsLong()).findFirst().orElse(-1);
        } catch (IOException | RuntimeException e) {
            return -1; // not written yet
        }
    }

    private static Path prefix() {
        String p = System.getProperty("stagecraft.playerStage");
        if (p == null || p.isBlank() || p.startsWith("${")) {
            fail("-Dstagecraft.playerStage=PREFIX is not set: this test needs a Player/Stage install "
                    + "(./stagecraft player-stage install --prefix PREFIX)");
        }
        Path prefix = Path.of(p).toAbsolutePath();
        if (!Files.isExecutable(prefix.resolve("bin/player")) || !Files.isRegularFile(prefix.resolve("env.sh"))) {
            fail(prefix + " is not a Player/Stage install made by ./stagecraft player-stage install (bin/player, env.sh)");
        }
        return prefix;
    }

    /** (time, x, y) of every position2d data message Player sent, read with {@code ./stagecraft decode}. */
    private static List<double[]> poses(Path log) throws IOException, InterruptedException {
        Path decoded = Files.createTempFile(Path.of("target").toAbsolutePath(), "decoded", ".jsonl");
        Process p = new ProcessBuilder(DemoRun.root().resolve("stagecraft").toString(), "decode", log.toString())
                .directory(DemoRun.root().toFile()).redirectOutput(decoded.toFile()).redirectError(ProcessBuilder.Redirect.INHERIT)
                .start();
        assertTrue(p.waitFor(180, TimeUnit.SECONDS), "./stagecraft decode ended");
        assertEquals(0, p.exitValue(), "./stagecraft decode " + log);
        List<double[]> out = new ArrayList<>();
        for (String line : Files.readAllLines(decoded)) {
            JsonObject o = JsonParser.parseString(line).getAsJsonObject();
            if (o.has("iface") && o.get("iface").getAsString().equals("position2d") && o.get("dir").getAsString().equals("s2c")
                    && o.get("type").getAsInt() == 1 && o.get("subtype").getAsInt() == 1) {
                JsonObject pos = o.getAsJsonObject("body").getAsJsonObject("pos");
                out.add(new double[] {o.get("t").getAsDouble(), pos.get("px").getAsDouble(), pos.get("py").getAsDouble()});
            }
        }
        return out;
    }

    private static void assertPortFree(String when) throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), 6665)) {
            throw new AssertionError(when + ": something listens on 6665 (" + s + ")");
        } catch (ConnectException expected) {
            // refused: free
        }
    }
}
