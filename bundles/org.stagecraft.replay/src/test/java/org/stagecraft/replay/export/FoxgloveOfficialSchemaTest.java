package org.stagecraft.replay.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.stagecraft.foxglove.FoxgloveSchemas;

import com.google.gson.Gson;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.networknt.schema.InputFormat;
import com.networknt.schema.JsonSchema;
import com.networknt.schema.JsonSchemaFactory;
import com.networknt.schema.SpecVersion;
import com.networknt.schema.ValidationMessage;

/**
 * The Foxglove schema tier: every message of an export of each corpus trace is valid against
 * Foxglove's official JSON Schema file for the schema its channel names, and the schemas the export
 * embeds (our own description, {@link FoxgloveSchemas}) have the official members and types.
 * Foxglove's files are not part of the project (MIT, in {@code ../shared/third-party/foxglove-schemas}
 * beside the checkout, or {@code -Dstagecraft.foxglove.schemas=DIR}); where they are absent these
 * tests are skipped, not passed, and {@code ./stagecraft test} says the tier was NOT run.
 */
class FoxgloveOfficialSchemaTest {
    /** The tier's folder, relative to the checkout's root. */
    static final String BESIDE_CHECKOUT = "../shared/third-party/foxglove-schemas";
    private static final JsonSchemaFactory FACTORY = JsonSchemaFactory.getInstance(SpecVersion.VersionFlag.V202012);
    private static Path dir;

    @BeforeAll
    static void locate() {
        dir = schemasDir();
        assumeTrue(dir != null, "Foxglove schema tier NOT run: no " + BESIDE_CHECKOUT
                + " beside the checkout and no -Dstagecraft.foxglove.schemas=DIR");
    }

    /** The official schema files, or null where they are not beside the checkout. */
    static Path schemasDir() {
        String prop = System.getProperty("stagecraft.foxglove.schemas");
        if (prop != null && !prop.isBlank()) {
            Path given = Path.of(prop);
            if (!Files.isRegularFile(given.resolve("LaserScan.json"))) {
                throw new IllegalStateException("-Dstagecraft.foxglove.schemas=" + prop + " has no LaserScan.json");
            }
            return given;
        }
        // the checkout's root is the folder with mvnw above the module the tests run in
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isRegularFile(p.resolve("mvnw")) && Files.isDirectory(p.resolve("bundles"))) {
                Path candidate = p.resolve(BESIDE_CHECKOUT).normalize();
                return Files.isRegularFile(candidate.resolve("LaserScan.json")) ? candidate : null;
            }
        }
        return null;
    }

    static List<Path> traces() {
        return FoxgloveExports.traces();
    }

    private static Path official(String schemaName) {
        assertTrue(schemaName.startsWith("foxglove."), schemaName);
        Path f = dir.resolve(schemaName.substring("foxglove.".length()) + ".json");
        assertTrue(Files.isRegularFile(f), "Foxglove has no schema " + schemaName + " (" + f + ")");
        return f;
    }

    @ParameterizedTest
    @MethodSource("traces")
    void everyExportedMessageIsValidAgainstTheOfficialSchemaItsChannelNames(Path trace) throws IOException {
        FoxgloveExports x = FoxgloveExports.of(trace);
        Map<String, JsonSchema> schemas = new HashMap<>();
        Map<String, Integer> validated = new TreeMap<>();
        for (FoxgloveExports.Msg m : x.messages()) {
            JsonSchema s = schemas.computeIfAbsent(m.schemaName(), n -> {
                try {
                    return FACTORY.getSchema(Files.readString(official(n), StandardCharsets.UTF_8));
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            });
            Set<ValidationMessage> errors = s.validate(m.json(), InputFormat.JSON);
            assertTrue(errors.isEmpty(), m.topic() + " at " + m.logTime() + " against " + official(m.schemaName()) + ": "
                    + errors);
            validated.merge(m.schemaName(), 1, Integer::sum);
        }
        assertTrue(validated.keySet().containsAll(Set.of("foxglove.FrameTransform", "foxglove.LaserScan",
                "foxglove.PoseInFrame", "foxglove.PosesInFrame", "foxglove.SceneUpdate", "foxglove.Log")),
                validated.toString());
        System.out.println("Foxglove schema tier: " + trace.getFileName() + ": " + validated);
    }

    @Test
    void devicesTheCorpusLacksAreValidAgainstTheOfficialSchemasToo() throws IOException {
        Map<String, Integer> validated = new TreeMap<>();
        for (SyntheticDevices.Sent m : SyntheticDevices.scene()) {
            JsonSchema s = FACTORY.getSchema(Files.readString(official(m.channel().schemaName())));
            Set<ValidationMessage> errors = s.validate(m.json(), InputFormat.JSON);
            assertTrue(errors.isEmpty(), m.channel().topic() + ": " + errors);
            validated.merge(m.channel().topic(), 1, Integer::sum);
        }
        assertTrue(validated.keySet().containsAll(Set.of("/robot6665/map0/grid", "/robot6665/bumper0/bumpers",
                "/robot6665/fiducial0/fiducials", "/robot6665/blobfinder0/blobs", "/robot6665/sonar0/cones")),
                validated.toString());
    }

    @Test
    void theOfficialSchemasRejectWhatFoxgloveWouldNotRead() throws IOException {
        JsonSchema log = FACTORY.getSchema(Files.readString(official("foxglove.Log")));
        String good = "{\"timestamp\":{\"sec\":1795315969,\"nsec\":5},\"level\":3,\"message\":\"m\",\"name\":\"n\","
                + "\"file\":\"\",\"line\":0}";
        assertTrue(log.validate(good, InputFormat.JSON).isEmpty());
        // a level Foxglove does not have, and nanoseconds past a second: what a wrong export would write
        assertTrue(!log.validate(good.replace("\"level\":3", "\"level\":9"), InputFormat.JSON).isEmpty());
        assertTrue(!log.validate(good.replace("\"nsec\":5", "\"nsec\":1000000000"), InputFormat.JSON).isEmpty());
        assertTrue(!log.validate(good.replace("\"message\":\"m\"", "\"message\":7"), InputFormat.JSON).isEmpty());
    }

    @Test
    void theEmbeddedSchemasHaveTheOfficialMembersAndTypes() throws IOException {
        for (String name : FoxgloveSchemas.NAMES) {
            JsonObject ours = JsonParser.parseString(new Gson().toJson(FoxgloveSchemas.describe(name))).getAsJsonObject();
            JsonObject theirs = JsonParser.parseString(Files.readString(official(name))).getAsJsonObject();
            assertEquals(theirs.get("title").getAsString(), ours.get("title").getAsString());
            sameShape(name, theirs, ours);
        }
    }

    /** Same members, recursively, and the same JSON type wherever the official schema gives one. */
    private static void sameShape(String where, JsonObject theirs, JsonObject ours) {
        if (theirs.has("type")) {
            assertEquals(theirs.get("type"), ours.get("type"), where + ": type");
        } else if (theirs.has("oneOf")) {
            // Foxglove's enums: oneOf of consts; ours: an integer enum of the same values
            java.util.List<Integer> values = new java.util.ArrayList<>();
            theirs.getAsJsonArray("oneOf").forEach(e -> values.add(e.getAsJsonObject().get("const").getAsInt()));
            java.util.List<Integer> mine = new java.util.ArrayList<>();
            ours.getAsJsonArray("enum").forEach(e -> mine.add(e.getAsInt()));
            assertEquals(values, mine, where + ": enum values");
        }
        if (theirs.has("properties")) {
            JsonObject tp = theirs.getAsJsonObject("properties"), op = ours.getAsJsonObject("properties");
            assertEquals(tp.keySet(), op == null ? Set.of() : op.keySet(), where + ": members");
            for (Map.Entry<String, JsonElement> e : tp.entrySet()) {
                sameShape(where + "." + e.getKey(), e.getValue().getAsJsonObject(), op.getAsJsonObject(e.getKey()));
            }
        }
        if (theirs.has("items")) {
            sameShape(where + "[]", theirs.getAsJsonObject("items"), ours.getAsJsonObject("items"));
        }
    }
}
