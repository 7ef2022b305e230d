package org.stagecraft.replay.export;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.foxglove.player.PlayerJson;
import org.stagecraft.foxglove.player.PlayerJsonSchema;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.log.Logs;
import org.stagecraft.replay.fields.FlatFields;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.writelog.WritelogWriter;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** CSV, writelog and MCAP exports of the shared traces, each read back and compared with the log. */
class ExportTest {
    private static final CodecRegistry REGISTRY = CodecRegistry.standard();
    private static final Path TRACE = TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl");

    private static List<LogMessage> frames(SessionLog log) throws IOException {
        return Logs.all(log).stream().filter(m -> m.kind() == LogMessage.Kind.FRAME).toList();
    }

    /** RFC 4180 rows (quoted cells allowed). */
    private static List<List<String>> parseCsv(String text) {
        List<List<String>> rows = new ArrayList<>();
        List<String> row = new ArrayList<>();
        StringBuilder cell = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (quoted) {
                if (c == '"' && i + 1 < text.length() && text.charAt(i + 1) == '"') {
                    cell.append('"');
                    i++;
                } else if (c == '"') {
                    quoted = false;
                } else {
                    cell.append(c);
                }
            } else if (c == '"') {
                quoted = true;
            } else if (c == ',') {
                row.add(cell.toString());
                cell.setLength(0);
            } else if (c == '\r') {
                // part of the row end
            } else if (c == '\n') {
                row.add(cell.toString());
                cell.setLength(0);
                rows.add(row);
                row = new ArrayList<>();
            } else {
                cell.append(c);
            }
        }
        return rows;
    }

    private static void assertSameValue(Object original, String cell, String where) {
        switch (original) {
            case Float f -> assertEquals(Float.floatToRawIntBits(f), Float.floatToRawIntBits(Float.parseFloat(cell)), where);
            case Double d -> assertEquals(Double.doubleToRawLongBits(d), Double.doubleToRawLongBits(Double.parseDouble(cell)), where);
            case Long l -> assertEquals(l.longValue(), Long.parseLong(cell), where);
            case byte[] b -> assertArrayEquals(b, HexFormat.of().parseHex(cell), where);
            default -> assertEquals(original.toString(), cell, where);
        }
    }

    @Test
    void csvHasARowPerMessageAndEveryNumberParsesBackExactly() throws IOException {
        try (SessionLog log = SessionLogs.open(TRACE)) {
            StringWriter out = new StringWriter();
            long rows = CsvExport.write(log, ExportFilter.all(), REGISTRY, out);
            List<LogMessage> frames = frames(log);
            assertEquals(frames.size(), rows);
            List<List<String>> csv = parseCsv(out.toString());
            assertEquals(rows + 1, csv.size());
            List<String> header = csv.get(0);
            assertEquals(CsvExport.FIXED, header.subList(0, CsvExport.FIXED.size()));
            assertTrue(header.contains("pos.px") && header.contains("ranges[179]"), "union of the kinds' columns");
            Map<String, Integer> col = new HashMap<>();
            for (int i = 0; i < header.size(); i++) {
                col.put(header.get(i), i);
            }
            for (int r = 0; r < frames.size(); r++) {
                LogMessage m = frames.get(r);
                List<String> cells = csv.get(r + 1);
                assertEquals(header.size(), cells.size());
                String where = "row " + (r + 1);
                MessageHeader h = m.decoded().header();
                assertEquals(m.timeNanos(), new java.math.BigDecimal(cells.get(0)).movePointRight(9).longValueExact(), where);
                assertEquals(m.connection().id(), Integer.parseInt(cells.get(1)), where);
                assertEquals(m.dir(), Direction.fromLabel(cells.get(2)), where);
                assertEquals(REGISTRY.interfaceName(h.interf()), cells.get(3), where);
                assertEquals(h.size(), Integer.parseInt(cells.get(7)), where);
                assertEquals(h.timestamp(), Double.parseDouble(cells.get(8)), where);
                Map<String, Object> fields = FlatFields.flatten(m.decoded().body());
                for (Map.Entry<String, Object> e : fields.entrySet()) {
                    assertSameValue(e.getValue(), cells.get(col.get(e.getKey())), where + " " + e.getKey());
                }
                long filled = 0;
                for (int i = CsvExport.FIXED.size(); i < cells.size(); i++) {
                    filled += cells.get(i).isEmpty() ? 0 : 1;
                }
                long nonEmpty = fields.values().stream().filter(v -> !CellText.of(v).isEmpty()).count();
                assertEquals(nonEmpty, filled, where + ": only this message's columns are filled");
            }
        }
    }

    @Test
    void filtersByStreamTimeAndText() throws IOException {
        try (SessionLog log = SessionLogs.open(TRACE)) {
            List<LogMessage> frames = frames(log);
            ExportFilter lasers = new ExportFilter(null, null, ExportFilter.parsePattern("dev=laser type=DATA", REGISTRY), null);
            StringWriter out = new StringWriter();
            long n = CsvExport.write(log, lasers, REGISTRY, out);
            long expected = frames.stream().filter(m -> m.decoded().header().interf() == 6 && m.decoded().header().type() == 1).count();
            assertEquals(expected, n);
            assertTrue(n > 100);
            for (List<String> row : parseCsv(out.toString()).subList(1, (int) n + 1)) {
                assertEquals("laser", row.get(3));
                assertEquals("SCAN", row.get(6));
            }

            ExportFilter window = new ExportFilter(5.0, 10.0, null, null);
            long start = log.startNanos();
            long inWindow = frames.stream().filter(m -> m.timeNanos() - start >= 5_000_000_000L
                    && m.timeNanos() - start <= 10_000_000_000L).count();
            assertEquals(inWindow, CsvExport.write(log, window, REGISTRY, new StringWriter()));
            assertTrue(inWindow > 0 && inWindow < frames.size());

            ExportFilter text = new ExportFilter(null, null, null, "GET_GEOM");
            long geoms = frames.stream().filter(m -> REGISTRY.subtypeName(m.decoded().header().interf(),
                    m.decoded().header().type(), m.decoded().header().subtype()).equals("GET_GEOM")).count();
            assertEquals(geoms, CsvExport.write(log, text, REGISTRY, new StringWriter()));
            assertTrue(geoms >= 4, "requests and replies of four devices");

            assertThrows(IllegalArgumentException.class, () -> ExportFilter.parsePattern("dev=nosuch", REGISTRY));
        }
    }

    @Test
    void writelogExportReadsBackToTheLogsData() throws IOException {
        try (SessionLog log = SessionLogs.open(TRACE)) {
            StringWriter out = new StringWriter();
            WritelogWriter.Summary s = WritelogExport.write(log, ExportFilter.all(), REGISTRY, out);
            assertTrue(out.toString().startsWith("## Player version 3.1.1-dev"), out.toString().substring(0, 40));
            assertTrue(s.written() > 1000);
            try (var r = new org.stagecraft.replay.writelog.WritelogReader("x",
                    new BufferedReader(new StringReader(out.toString())))) {
                long n = 0;
                while (r.next() != null) {
                    n++;
                }
                assertEquals(s.written(), n);
                assertEquals(List.of(), r.problems());
            }
        }
    }

    /**
     * Player's readlog keeps replies only from the file's leading reply lines (it stops looking at
     * the first line that is not a reply) and answers GET_GEOM / GET_CONFIG from those alone.
     */
    @Test
    void writelogExportLeadsWithEveryDevicesGeometryAndConfigReplies() throws IOException {
        StringWriter out = new StringWriter();
        try (SessionLog log = SessionLogs.open(TRACE)) {
            WritelogExport.write(log, ExportFilter.all(), REGISTRY, out);
        }
        List<String[]> lines = out.toString().lines().filter(l -> !l.isBlank() && !l.startsWith("#"))
                .map(l -> l.trim().split("\\s+")).toList();
        int firstData = 0;
        while (firstData < lines.size() && lines.get(firstData)[5].equals("4")) {
            firstData++;
        }
        java.util.Set<String> leading = new java.util.TreeSet<>();
        for (String[] l : lines.subList(0, firstData)) {
            leading.add(l[3] + ":" + l[4] + " " + l[6]); // interface:index subtype
        }
        assertTrue(firstData > 0, "the file starts with replies");
        for (int i = firstData; i < lines.size(); i++) {
            assertTrue(!lines.get(i)[5].equals("4"), "reply after the first data line: " + String.join(" ", lines.get(i)));
        }
        // every geometry reply the recorded robot program got must be among them, although in the
        // session some came after data had flowed
        java.util.Set<String> asked = new java.util.TreeSet<>();
        boolean dataBeforeAReply = false;
        boolean dataSeen = false;
        try (SessionLog log = SessionLogs.open(TRACE)) {
            for (LogMessage m : org.stagecraft.replay.log.Logs.all(log)) {
                if (m.kind() != LogMessage.Kind.FRAME || m.decoded() == null || m.dir() != Direction.SERVER_TO_CLIENT) {
                    continue;
                }
                MessageHeader h = m.decoded().header();
                if (WritelogWriter.isReply(m) && h.subtype() == 1) { // GET_GEOM is subtype 1 in every interface here
                    asked.add(REGISTRY.interfaceName(h.interf()) + ":" + h.index() + " 1");
                    dataBeforeAReply |= dataSeen;
                } else if (h.type() == 1) {
                    dataSeen = true;
                }
            }
        }
        assertTrue(asked.contains("position2d:0 1"), "the recording has geometry replies: " + asked);
        assertTrue(dataBeforeAReply, "the recording has data before a reply, so the order matters");
        assertTrue(leading.containsAll(asked), "asked " + asked + ", leading replies " + leading);
        assertTrue(firstData < lines.size() && lines.get(firstData)[5].equals("1"), "data follows the replies");
    }

    @Test
    void mcapExportHasEveryMessageAsJsonAndStaysACompleteSpyLog() throws IOException {
        Path out = Files.createDirectories(Path.of("target", "test-logs")).resolve("export-gt.mcap");
        try (SessionLog log = SessionLogs.open(TRACE)) {
            McapExport.Summary s = McapExport.write(log, ExportFilter.all(), REGISTRY, out);
            List<LogMessage> all = Logs.all(log);
            List<LogMessage> frames = all.stream().filter(m -> m.kind() == LogMessage.Kind.FRAME).toList();
            assertEquals(frames.size(), s.jsonMessages());

            McapMessages mcap = McapMessages.read(out);
            Map<String, List<McapMessages.Message>> byTopic = new LinkedHashMap<>();
            for (McapMessages.Message m : mcap.messages) {
                McapMessages.Channel c = mcap.channels.get(m.channel());
                McapMessages.Schema schema = mcap.schemas.get(c.schemaId());
                // Player's decoded channels; the Foxglove ones are checked in FoxgloveExportTest
                if (c.encoding().equals("json") && !c.topic().equals("/events") && !schema.name().startsWith("foxglove.")) {
                    assertNotNull(schema, c.topic());
                    assertEquals("jsonschema", schema.encoding());
                    byTopic.computeIfAbsent(c.topic(), k -> new ArrayList<>()).add(m);
                }
            }
            assertEquals(s.jsonChannels(), byTopic.size());
            assertTrue(byTopic.containsKey("/6665/1/laser:0/DATA/SCAN"), byTopic.keySet().toString());
            Map<String, Integer> next = new HashMap<>();
            for (LogMessage m : frames) {
                String topic = McapExport.topic(REGISTRY, m.connection().port(), m.connection().id(), m.decoded().header());
                int i = next.merge(topic, 1, Integer::sum) - 1;
                McapMessages.Message jm = byTopic.get(topic).get(i);
                String where = topic + " #" + i;
                assertEquals(m.timeNanos(), jm.logTime(), where);
                JsonObject o = JsonParser.parseString(new String(jm.data(), StandardCharsets.UTF_8)).getAsJsonObject();
                assertEquals(m.decoded().header().timestamp(), o.getAsJsonObject("header").get("timestamp").getAsDouble(), where);
                for (Map.Entry<String, Object> e : FlatFields.flatten(m.decoded().body()).entrySet()) {
                    JsonElement v = at(o, e.getKey());
                    assertNotNull(v, where + " " + e.getKey());
                    switch (e.getValue()) {
                        case Float f -> assertEquals(f, v.getAsFloat(), where + " " + e.getKey());
                        case Double d -> assertEquals(d, v.getAsDouble(), where + " " + e.getKey());
                        case Long l -> assertEquals(l, v.getAsLong(), where + " " + e.getKey());
                        case byte[] b -> assertArrayEquals(b, java.util.Base64.getDecoder().decode(v.getAsString()));
                        default -> assertEquals(e.getValue().toString(), v.getAsString(), where + " " + e.getKey());
                    }
                }
            }
            // nothing lost: the export opens as a spy log with the same wire bytes
            try (SessionLog back = SessionLogs.open(out)) {
                assertEquals(LogFormat.SPY_LOG, back.format());
                List<LogMessage> again = Logs.all(back);
                List<LogMessage> wire = all.stream().filter(m -> m.kind() != LogMessage.Kind.OPENED
                        && m.kind() != LogMessage.Kind.CLOSED && m.kind() != LogMessage.Kind.DIAGNOSTIC).toList();
                List<LogMessage> wireAgain = again.stream().filter(m -> m.kind() != LogMessage.Kind.OPENED
                        && m.kind() != LogMessage.Kind.CLOSED && m.kind() != LogMessage.Kind.DIAGNOSTIC).toList();
                assertEquals(wire.size(), wireAgain.size());
                for (int i = 0; i < wire.size(); i++) {
                    assertArrayEquals(wire.get(i).bytes(), wireAgain.get(i).bytes(), "wire entry " + i);
                    assertEquals(wire.get(i).timeNanos(), wireAgain.get(i).timeNanos());
                }
                assertEquals(log.connections().size(), back.connections().size());
            }
        }
    }

    @Test
    void twoClientsOfOneDeviceAreTwoChannelsEachWithItsConnectionsMessagesOnly() throws IOException {
        Path sonar = TraceCorpus.file("pioneer-laser-sonar.sonar.trace.jsonl");
        Path out = Files.createDirectories(Path.of("target", "test-logs")).resolve("export-sonar.mcap");
        try (SessionLog log = SessionLogs.open(sonar)) {
            List<LogMessage> frames = frames(log);
            McapExport.Summary s = McapExport.write(log, ExportFilter.all(), REGISTRY, out);
            assertEquals(frames.size(), s.jsonMessages(), "each message once");
            Map<String, Long> expected = new LinkedHashMap<>();
            for (LogMessage m : frames) {
                expected.merge(McapExport.topic(REGISTRY, m.connection().port(), m.connection().id(), m.decoded().header()),
                        1L, Long::sum);
            }
            McapMessages mcap = McapMessages.read(out);
            Map<String, Long> got = new LinkedHashMap<>();
            Map<String, Integer> channelOfTopic = new HashMap<>();
            for (McapMessages.Message m : mcap.messages) {
                McapMessages.Channel c = mcap.channels.get(m.channel());
                if (c.encoding().equals("json") && !c.topic().equals("/events")
                        && !mcap.schemas.get(c.schemaId()).name().startsWith("foxglove.")) {
                    got.merge(c.topic(), 1L, Long::sum);
                    Integer before = channelOfTopic.putIfAbsent(c.topic(), c.id());
                    assertTrue(before == null || before == c.id(), "one channel per stream: " + c.topic());
                    assertEquals(c.topic().split("/")[2], c.metadata().get("conn"), c.topic());
                }
            }
            assertEquals(expected, got);
            // both clients talk to the server's own device (player:0): its SYNCHs are two streams, two channels
            assertTrue(got.containsKey("/6665/1/player:0/SYNCH/OK") && got.containsKey("/6665/2/player:0/SYNCH/OK"),
                    got.keySet().toString());
        }
    }

    @Test
    void aChannelsSchemaIsTheUnionOfItsLayoutsSoEveryMessageValidates() {
        // Player's NACK to a subscription carries a device request; NACKs are documented without body
        int dev = 3;
        MessageHeader h = new MessageHeader(0, 6665, 1, 0, org.stagecraft.player.wire.MessageType.RESP_NACK.code(), dev, 1.5,
                0, 0);
        byte[] req = HexFormat.of().parseHex("00000000" + "00001a09" + "00000004" + "00000000" + "00000003"
                + "00000000" + "00000000");
        org.stagecraft.player.codec.PlayerDecoder decoder = new org.stagecraft.player.codec.PlayerDecoder(REGISTRY);
        var withBody = decoder.decode(new MessageHeader(0, 6665, 1, 0, h.type(), dev, 1.5, 0, req.length), req);
        var without = decoder.decode(h, new byte[0]);
        JsonObject bodyJson = JsonParser.parseString(PlayerJson.of(withBody.header(), withBody.body())).getAsJsonObject();
        JsonObject emptyJson = JsonParser.parseString(PlayerJson.of(without.header(), without.body())).getAsJsonObject();
        assertTrue(bodyJson.size() > emptyJson.size(), "the two layouts differ: " + bodyJson + " / " + emptyJson);

        JsonObject first = JsonParser.parseString(PlayerJsonSchema.text("t", PlayerJsonSchema.of(without.body()))).getAsJsonObject();
        assertTrue(!first.getAsJsonObject("properties").keySet().containsAll(bodyJson.keySet()),
                "a schema from the first (empty) NACK alone does not describe the other");

        PlayerJsonSchema.Node union = PlayerJsonSchema.of(without.body()).merge(PlayerJsonSchema.of(withBody.body()));
        JsonObject schema = JsonParser.parseString(PlayerJsonSchema.text("player RESP_NACK DEV", union)).getAsJsonObject();
        assertEquals(bodyJson.keySet(), schema.getAsJsonObject("properties").keySet(), "every member seen is described");
        assertEquals(List.of("header"), schema.getAsJsonArray("required").asList().stream().map(JsonElement::getAsString).toList(),
                "only what every layout has is required");
        assertEquals("", violations(bodyJson, schema, "$"));
        assertEquals("", violations(emptyJson, schema, "$"));
        JsonObject wrong = bodyJson.deepCopy();
        wrong.remove("header");
        assertTrue(violations(wrong, schema, "$").contains("no header"), "the checker can fail");
    }

    /** A small JSON Schema check of what the export writes: type, properties, required, items, anyOf. */
    private static String violations(JsonElement v, JsonObject schema, String where) {
        if (schema.has("anyOf")) {
            for (JsonElement alt : schema.getAsJsonArray("anyOf")) {
                if (violations(v, alt.getAsJsonObject(), where).isEmpty()) {
                    return "";
                }
            }
            return where + ": fits no alternative; ";
        }
        if (!schema.has("type")) {
            return "";
        }
        String type = schema.get("type").getAsString();
        StringBuilder out = new StringBuilder();
        switch (type) {
            case "object" -> {
                if (!v.isJsonObject()) {
                    return where + ": not an object; ";
                }
                JsonObject o = v.getAsJsonObject();
                if (schema.has("required")) {
                    for (JsonElement r : schema.getAsJsonArray("required")) {
                        if (!o.has(r.getAsString())) {
                            out.append(where).append(": no ").append(r.getAsString()).append("; ");
                        }
                    }
                }
                JsonObject props = schema.has("properties") ? schema.getAsJsonObject("properties") : new JsonObject();
                for (String k : o.keySet()) {
                    if (props.has(k)) {
                        out.append(violations(o.get(k), props.getAsJsonObject(k), where + "." + k));
                    } else {
                        out.append(where).append(": ").append(k).append(" not described; ");
                    }
                }
            }
            case "array" -> {
                if (!v.isJsonArray()) {
                    return where + ": not an array; ";
                }
                int i = 0;
                for (JsonElement e : v.getAsJsonArray()) {
                    out.append(violations(e, schema.getAsJsonObject("items"), where + "[" + i++ + "]"));
                }
            }
            case "string" -> {
                if (!(v.isJsonPrimitive() && v.getAsJsonPrimitive().isString())) {
                    out.append(where).append(": not a string; ");
                }
            }
            case "null" -> {
                if (!v.isJsonNull()) {
                    out.append(where).append(": not null; ");
                }
            }
            case "integer", "number" -> {
                if (!(v.isJsonPrimitive() && v.getAsJsonPrimitive().isNumber())
                        || type.equals("integer") && v.getAsString().contains(".")) {
                    out.append(where).append(": not ").append(type).append("; ");
                }
            }
            default -> out.append(where).append(": unknown type ").append(type).append("; ");
        }
        return out.toString();
    }

    /** The JSON value at a flat path like "pos.px" or "ranges[3]" or "poses[2].px". */
    private static JsonElement at(JsonObject root, String path) {
        JsonElement cur = root;
        for (String part : path.split("\\.")) {
            int bracket = part.indexOf('[');
            String name = bracket < 0 ? part : part.substring(0, bracket);
            cur = cur.getAsJsonObject().get(name);
            while (bracket >= 0 && cur != null) {
                int close = part.indexOf(']', bracket);
                cur = cur.getAsJsonArray().get(Integer.parseInt(part.substring(bracket + 1, close)));
                bracket = part.indexOf('[', close);
            }
        }
        return cur;
    }
}
