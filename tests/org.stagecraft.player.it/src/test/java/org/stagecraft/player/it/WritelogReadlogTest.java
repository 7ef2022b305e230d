package org.stagecraft.player.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Issue 18: a writelog export, made as a user makes it ({@code ./stagecraft export TRACE --format
 * writelog}), served by the real Player's {@code readlog} driver: libplayerc's geometry requests
 * (GET_GEOM) of position2d, laser and both rangers are ACKed with the recording's values, and the data
 * Player serves are the recorded poses, scans and sonar ranges.
 */
@Timeout(value = 240, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WritelogReadlogTest {
    private static final String TRACE = "tests/traces/pioneer-laser-sonar.gt.trace.jsonl";
    /** The port the recording was made on: the "robot" of every exported line. */
    private static final String RECORDED_PORT = "7665";
    private static final int ROUNDS = 100; // 10 s of the recording at speed 2 (readlog at speed 5 stopped answering here)

    @TempDir
    Path tmp;

    /** One line of the export: interface, index, type, subtype, and the values after the header. */
    private record Line(String iface, int index, int type, int subtype, List<String> values) {
        double at(int i) {
            return Double.parseDouble(values.get(i));
        }
    }

    @Test
    void aWritelogExportServedByReadlogAnswersGeometryRequestsAndServesTheRecordedValues() throws Exception {
        // the export, as README shows it
        Path log = tmp.resolve("session.log");
        PlayerStage.Program export = new PlayerStage.Program("stagecraft export", List.of(
                PlayerStage.root().resolve("stagecraft").toString(), "export", PlayerStage.root().resolve(TRACE).toString(),
                "--format", "writelog", "--out", log.toString()), Map.of(), PlayerStage.root());
        assertEquals(0, export.awaitExit(Duration.ofSeconds(180)), export.output());

        // Player binds every address: the recorded port may be taken, so the lines are moved to a free one
        // (the "robot" field, which readlog matches against the port of its provided devices)
        int port = PlayerStage.freePorts(1).get(0);
        List<String> moved = new ArrayList<>();
        List<Line> lines = new ArrayList<>();
        for (String l : Files.readAllLines(log)) {
            if (l.startsWith("#") || l.isBlank()) {
                moved.add(l);
                continue;
            }
            String[] t = l.trim().split("\\s+");
            assertEquals(RECORDED_PORT, t[2], "every line is of the recorded Player port: " + l);
            t[2] = String.valueOf(port);
            moved.add(String.join(" ", t));
            lines.add(new Line(t[3], Integer.parseInt(t[4]), Integer.parseInt(t[5]), Integer.parseInt(t[6]),
                    List.of(t).subList(7, t.length)));
        }
        Path served = Files.write(tmp.resolve("served.log"), moved);
        Path cfg = Files.writeString(tmp.resolve("readlog.cfg"), """
                driver
                (
                  name "readlog"
                  filename "%s"
                  provides ["position2d:0" "laser:0" "ranger:0" "ranger:1"]
                  speed 2.0
                  autoplay 1
                )
                """.formatted(served));

        Map<String, String> env = PlayerStage.env();
        if (!env.containsKey("PYTHONPATH")) {
            fail("libplayerc's Python bindings were not built into " + PlayerStage.prefix() + " (no PYTHONPATH in env.sh)");
        }
        try (PlayerStage.Program player = new PlayerStage.Program("player", List.of("stdbuf", "-oL",
                PlayerStage.player().toString(), "-p", String.valueOf(port), cfg.toString()), env, tmp)) {
            assertTrue(PlayerStage.await(Duration.ofSeconds(30), () -> !PlayerStage.isFree(port)),
                    "Player listens on " + port + ": " + player.output());
            String py = env.getOrDefault("STAGECRAFT_PLAYERC_PYTHON", "/usr/bin/python3");
            JsonObject read;
            try (PlayerStage.Program client = new PlayerStage.Program("readlog_read.py", List.of(py,
                    PlayerStage.script("readlog_read.py").toString(), "127.0.0.1", String.valueOf(port),
                    String.valueOf(ROUNDS)), env, null)) {
                assertEquals(0, client.awaitExit(Duration.ofSeconds(120)), client.output() + "\nPlayer:\n" + player.output());
                read = JsonParser.parseString(client.lines.stream().filter(l -> l.startsWith("{")).findFirst()
                        .orElseThrow(() -> new AssertionError("no JSON from libplayerc: " + client.output())))
                        .getAsJsonObject();
            }

            // geometry: ACKed, with the values of the export's leading reply lines
            JsonObject geom = read.getAsJsonObject("geom");
            Line pg = only(lines, "position2d", 0, 4, 1);
            JsonObject p = geom.getAsJsonObject("position2d:0");
            assertTrue(p.get("ack").getAsBoolean(), "position2d GET_GEOM answered: " + p);
            assertValues(List.of(pg.at(0), pg.at(1), pg.at(2)), p.getAsJsonArray("pose"), 1e-12, "position2d pose");
            assertValues(List.of(pg.at(3), pg.at(4)), p.getAsJsonArray("size"), 1e-12, "position2d size");
            Line lg = only(lines, "laser", 0, 4, 1);
            JsonObject l = geom.getAsJsonObject("laser:0");
            assertTrue(l.get("ack").getAsBoolean(), "laser GET_GEOM answered: " + l);
            assertValues(List.of(lg.at(0), lg.at(1), lg.at(2)), l.getAsJsonArray("pose"), 1e-12, "laser pose");
            assertValues(List.of(lg.at(3), lg.at(4)), l.getAsJsonArray("size"), 1e-12, "laser size");
            for (int index : new int[] {0, 1}) {
                Line rg = only(lines, "ranger", index, 4, 1);
                JsonObject r = geom.getAsJsonObject("ranger:" + index);
                assertTrue(r.get("ack").getAsBoolean(), "ranger:" + index + " GET_GEOM answered: " + r);
                assertValues(List.of(rg.at(0), rg.at(1), rg.at(2), rg.at(3), rg.at(4), rg.at(5)),
                        r.getAsJsonArray("device_pose"), 1e-12, "ranger:" + index + " pose");
                assertValues(List.of(rg.at(6), rg.at(7), rg.at(8)), r.getAsJsonArray("device_size"), 1e-12,
                        "ranger:" + index + " size");
                assertEquals((int) rg.at(9), r.get("element_count").getAsInt(), "ranger:" + index + " elements");
            }
            assertEquals(16, geom.getAsJsonObject("ranger:0").get("element_count").getAsInt(), "the 16 sonars");

            // data: what the client got is what was recorded, and it moves on through the recording
            List<List<Double>> recordedPoses = lines.stream().filter(x -> is(x, "position2d", 0, 1, 1))
                    .map(x -> List.of(x.at(0), x.at(1), x.at(2))).toList();
            List<List<Double>> recordedScans = new ArrayList<>();
            for (Line x : lines) {
                if (is(x, "laser", 0, 1, 1)) { // id min max res max_range count, then range intensity pairs
                    int n = (int) x.at(5);
                    List<Double> r = new ArrayList<>();
                    for (int i = 0; i < n; i++) {
                        r.add(x.at(6 + 2 * i));
                    }
                    recordedScans.add(r);
                }
            }
            List<List<Double>> recordedSonar = lines.stream().filter(x -> is(x, "ranger", 0, 1, 1))
                    .map(x -> x.values().subList(1, 1 + (int) x.at(0)).stream().map(Double::parseDouble).toList()).toList();
            checkServed("pose", read.getAsJsonArray("poses"), recordedPoses, 1e-12);
            checkServed("laser scan", read.getAsJsonArray("scans"), recordedScans, 1e-6); // floats in the file
            checkServed("sonar ranges", read.getAsJsonArray("sonar"), recordedSonar, 1e-12);

            assertFalse(player.anyLine(x -> x.toLowerCase().contains("error")), "no error from Player: " + player.output());
        }
        assertTrue(PlayerStage.await(Duration.ofSeconds(10), () -> PlayerStage.isFree(port)), "Player's port is free again");
    }

    private static boolean is(Line l, String iface, int index, int type, int subtype) {
        return l.iface().equals(iface) && l.index() == index && l.type() == type && l.subtype() == subtype;
    }

    private static Line only(List<Line> lines, String iface, int index, int type, int subtype) {
        List<Line> found = lines.stream().filter(l -> is(l, iface, index, type, subtype)).toList();
        assertEquals(1, found.size(), "one " + iface + ":" + index + " " + type + ":" + subtype + " line in the export");
        return found.get(0);
    }

    private static void assertValues(List<Double> expected, JsonArray actual, double tolerance, String what) {
        assertEquals(expected.size(), actual.size(), what + ": " + actual);
        for (int i = 0; i < expected.size(); i++) {
            assertEquals(expected.get(i), actual.get(i).getAsDouble(), tolerance, what + " [" + i + "]: " + actual);
        }
    }

    /**
     * Every value the client read is one of the recorded ones, there are many, and more than one
     * distinct (readlog went on through the file, not just repeated its first line).
     */
    private static void checkServed(String what, JsonArray read, List<List<Double>> recorded, double tolerance) {
        assertTrue(read.size() >= 20, "libplayerc got " + what + " data again and again: " + read.size());
        Set<Integer> matched = new HashSet<>();
        for (JsonElement e : read) {
            List<Double> got = e.getAsJsonArray().asList().stream().map(JsonElement::getAsDouble).toList();
            int at = -1;
            for (int i = 0; i < recorded.size() && at < 0; i++) {
                if (close(recorded.get(i), got, tolerance)) {
                    at = i;
                }
            }
            assertTrue(at >= 0, "the served " + what + " " + got + " is one of the " + recorded.size() + " recorded");
            matched.add(at);
        }
        assertTrue(matched.size() >= 2, "Player served more than one recorded " + what + ": " + matched);
    }

    private static boolean close(List<Double> a, List<Double> b, double tolerance) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0; i < a.size(); i++) {
            if (Math.abs(a.get(i) - b.get(i)) > tolerance * Math.max(1, Math.abs(a.get(i)))) {
                return false;
            }
        }
        return true;
    }
}
