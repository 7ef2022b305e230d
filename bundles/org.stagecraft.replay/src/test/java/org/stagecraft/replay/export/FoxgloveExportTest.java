package org.stagecraft.replay.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;

import com.google.gson.JsonObject;
import com.networknt.schema.InputFormat;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;

/**
 * The Foxglove part of MCAP exports of every corpus trace, without Foxglove's own schema files (those
 * are checked in {@link FoxgloveOfficialSchemaTest}, where they lie beside the checkout): each
 * message is valid against the schema its channel embeds, frames chain from the world to every
 * frame a message is in, times are the capture's real dates, and each robot is there.
 */
class FoxgloveExportTest {
    private static final JsonSchemaFactory SCHEMAS = JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V202012);

    static List<Path> traces() {
        return FoxgloveExports.traces();
    }

    @ParameterizedTest
    @MethodSource("traces")
    void everyMessageIsValidAgainstTheSchemaItsChannelEmbeds(Path trace) throws IOException {
        FoxgloveExports x = FoxgloveExports.of(trace);
        Map<String, JsonSchema> byText = new HashMap<>();
        for (FoxgloveExports.Msg m : x.messages()) {
            JsonSchema s = byText.computeIfAbsent(m.embeddedSchema(), SCHEMAS::getSchema);
            Set<ValidationMessage> errors = s.validate(m.json(), InputFormat.JSON);
            assertTrue(errors.isEmpty(), m.topic() + " at " + m.logTime() + ": " + errors);
        }
        Set<String> schemas = new TreeSet<>();
        x.messages().forEach(m -> schemas.add(m.schemaName()));
        // every corpus trace drives a Pioneer with odometry and a laser, and opens a connection
        assertTrue(schemas.containsAll(Set.of("foxglove.FrameTransform", "foxglove.PoseInFrame", "foxglove.LaserScan",
                "foxglove.SceneUpdate", "foxglove.Log")), trace + ": " + schemas);
    }

    @ParameterizedTest
    @MethodSource("traces")
    void framesChainFromTheWorldToEverySensorAndTimesAreRealDates(Path trace) throws IOException {
        FoxgloveExports x = FoxgloveExports.of(trace);
        Map<String, String> parent = new HashMap<>();
        Set<String> framesUsed = new TreeSet<>();
        long last = Long.MIN_VALUE;
        for (FoxgloveExports.Msg m : x.messages()) {
            assertTrue(m.logTime() >= last, "out of order at " + m.topic());
            last = m.logTime();
            // the recordings were made in 2026: a time near 1970 means the trace's relative times leaked
            assertTrue(m.logTime() > Instant.parse("2020-01-01T00:00:00Z").getEpochSecond() * 1_000_000_000L,
                    m.topic() + " at " + m.logTime());
            JsonObject o = m.object();
            List<String> frames = new ArrayList<>();
            switch (m.schemaName()) {
                case "foxglove.FrameTransform" -> parent.put(o.get("child_frame_id").getAsString(),
                        o.get("parent_frame_id").getAsString());
                case "foxglove.SceneUpdate" -> o.getAsJsonArray("entities")
                        .forEach(e -> frames.add(e.getAsJsonObject().get("frame_id").getAsString()));
                case "foxglove.Log" -> {
                }
                default -> frames.add(o.get("frame_id").getAsString());
            }
            if (!m.schemaName().equals("foxglove.Log")) {
                JsonObject stamp = m.schemaName().equals("foxglove.SceneUpdate")
                        ? o.getAsJsonArray("entities").get(0).getAsJsonObject().getAsJsonObject("timestamp")
                        : o.getAsJsonObject("timestamp");
                assertEquals(m.logTime(), stamp.get("sec").getAsLong() * 1_000_000_000L + stamp.get("nsec").getAsLong(),
                        "a message's timestamp is its capture time: " + m.topic());
            }
            for (String f : frames) {
                framesUsed.add(f);
                String at = f;
                for (int hops = 0; !at.equals("world"); hops++) {
                    assertTrue(hops < 10, "a cycle above " + f);
                    String up = parent.get(at);
                    assertNotNull(up, "frame " + at + " (of " + m.topic() + " at " + m.logTime()
                            + ") has no transform towards the world yet");
                    at = up;
                }
            }
        }
        assertTrue(framesUsed.contains("robot6665/laser0"), framesUsed.toString());
        assertEquals(List.of("robot6665"), x.summary().robots(), "every corpus recording is of one robot on port 6665");
    }

    @Test
    void mapsBumpersFiducialsBlobsAndSonarBecomeGridsAndSceneUpdates() {
        Map<String, JsonObject> last = new HashMap<>();
        for (SyntheticDevices.Sent m : SyntheticDevices.scene()) {
            Set<ValidationMessage> errors = SCHEMAS.getSchema(m.channel().schema()).validate(m.json(), InputFormat.JSON);
            assertTrue(errors.isEmpty(), m.channel().topic() + ": " + errors);
            last.put(m.channel().topic(), com.google.gson.JsonParser.parseString(m.json()).getAsJsonObject());
        }
        // Player's map cells (-1 free, 0 unknown, +1 occupied) in the convention Foxglove colours: 0, -1, 100
        JsonObject grid = last.get("/robot6665/map0/grid");
        assertEquals(4, grid.get("column_count").getAsInt());
        assertEquals("world", grid.get("frame_id").getAsString());
        byte[] cells = java.util.Base64.getDecoder().decode(grid.get("data").getAsString());
        assertEquals(java.util.Arrays.toString(new byte[] { 0, 0, -1, 100, 0, 100, 100, -1, -1, -1, 0, 0 }),
                java.util.Arrays.toString(cells));
        // bumper 0 pressed (red), bumper 1 not
        var cubes = last.get("/robot6665/bumper0/bumpers").getAsJsonArray("entities").get(0).getAsJsonObject()
                .getAsJsonArray("cubes");
        assertEquals(2, cubes.size());
        assertEquals(1.0, cubes.get(0).getAsJsonObject().getAsJsonObject("color").get("r").getAsDouble());
        assertTrue(cubes.get(1).getAsJsonObject().getAsJsonObject("color").get("r").getAsDouble() < 0.5);
        var texts = last.get("/robot6665/fiducial0/fiducials").getAsJsonArray("entities").get(0).getAsJsonObject()
                .getAsJsonArray("texts");
        assertEquals("fiducial 7", texts.get(0).getAsJsonObject().get("text").getAsString());
        // the blob at pixel column 20 of 80: a quarter of the 60 degree field of view left of the axis, 2.5 m away
        var blob = last.get("/robot6665/blobfinder0/blobs").getAsJsonArray("entities").get(0).getAsJsonObject()
                .getAsJsonArray("cubes").get(0).getAsJsonObject().getAsJsonObject("pose").getAsJsonObject("position");
        assertEquals(2.5 * Math.cos(Math.toRadians(15)), blob.get("x").getAsDouble(), 1e-9);
        assertEquals(2.5 * Math.sin(Math.toRadians(15)), blob.get("y").getAsDouble(), 1e-9);
        // 8 transducers, one at range 0 (no cone): 7 cones of 6 slices
        var cones = last.get("/robot6665/sonar0/cones").getAsJsonArray("entities").get(0).getAsJsonObject()
                .getAsJsonArray("triangles").get(0).getAsJsonObject().getAsJsonArray("points");
        assertEquals(7 * 6 * 3, cones.size());
    }

    @Test
    void sensorsSitWhereTheirGeometrySaysAndEveryScanIsExported() throws IOException {
        FoxgloveExports x = FoxgloveExports.of(FoxgloveExports.traces().stream()
                .filter(p -> p.getFileName().toString().equals("pioneer-laser-sonar.gt.trace.jsonl")).findFirst().orElseThrow());
        Map<String, Integer> perTopic = new HashMap<>();
        JsonObject rangerTf = null;
        for (FoxgloveExports.Msg m : x.messages()) {
            perTopic.merge(m.topic(), 1, Integer::sum);
            if (m.schemaName().equals("foxglove.FrameTransform")
                    && m.object().get("child_frame_id").getAsString().equals("robot6665/ranger1")) {
                rangerTf = m.object();
            }
        }
        int playerScans = 0, playerSonar = 0;
        for (McapMessages.Message m : x.all().messages) {
            String topic = x.all().channels.get(m.channel()).topic();
            playerScans += topic.equals("/6665/1/laser:0/DATA/SCAN") ? 1 : 0;
            playerSonar += topic.equals("/6665/1/ranger:0/DATA/RANGE") ? 1 : 0;
        }
        assertTrue(playerScans > 500, "scans in the recording: " + playerScans);
        assertEquals(playerScans, perTopic.get("/robot6665/laser0/scan"));
        // the sonar ring's data before its geometry reply has no place for cones; every later one has
        assertTrue(perTopic.get("/robot6665/ranger0/cones") >= playerSonar - 2, perTopic.toString());
        assertTrue(!perTopic.containsKey("/robot6665/ranger0/scan"), "the sonar ring is no laser: " + perTopic.keySet());
        assertNotNull(rangerTf, "the laser ranger has a frame");
        // ranger:1's GET_GEOM reply in this recording: device at the robot's origin, its one element 0.1 m up
        assertEquals(0.1, rangerTf.getAsJsonObject("translation").get("z").getAsDouble(), 1e-12,
                "ranger1 is placed by its geometry: " + rangerTf);
    }
}
