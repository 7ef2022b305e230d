package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.xdr.XdrReader;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import org.stagecraft.recording.trace.TraceCorpus;

class MainTest {

    /** The shared recordings; the build passes their folder (see the parent pom). */
    private static Path trace(String name) {
        return TraceCorpus.file(name);
    }

    private static CommandRun run(String... args) {
        return CommandRun.of(args);
    }

    @Test
    void decodePrintsOneJsonObjectPerBannerAndMessageInStreamOrder() {
        CommandRun r = run("decode", trace("requests.reqclient.trace.jsonl").toString());
        assertEquals(0, r.code(), r.err());
        List<JsonObject> lines = r.json();
        assertEquals("Player v.3.1.1-dev", lines.get(0).get("ident").getAsString());
        JsonObject first = lines.get(1);
        assertEquals("c2s", first.get("dir").getAsString());
        assertEquals("player", first.get("iface").getAsString());
        assertEquals(2, first.getAsJsonObject("body").get("mode").getAsInt(), "libplayerc asks for PULL first");
        double lastT = 0;
        for (JsonObject o : lines) {
            assertFalse(o.has("error"), o.toString());
            assertTrue(o.get("t").getAsDouble() >= lastT, "stream order");
            lastT = o.get("t").getAsDouble();
        }
        assertEquals(1281, lines.size());
    }

    @Test
    void numbersParseBackToTheExactWireValues() {
        CommandRun r = run("decode", trace("pioneer-laser-sonar.gt.trace.jsonl").toString());
        JsonObject scan = r.json().stream().filter(o -> "laser".equals(o.has("iface") ? o.get("iface").getAsString() : "")
                && o.get("type").getAsInt() == 1).findFirst().orElseThrow();
        JsonObject body = scan.getAsJsonObject("body");
        assertEquals(180, body.get("ranges_count").getAsInt());
        JsonArray ranges = body.getAsJsonArray("ranges");
        assertEquals(180, ranges.size());
        // ground truth: libplayerc decoded 1.4891668558120728 (the float widened to double)
        assertEquals(1.4891668558120728, ranges.get(0).getAsDouble());
        assertEquals(-1.57079637f, body.get("min_angle").getAsFloat());
        assertEquals(0.8, scan.get("timestamp").getAsDouble());
    }

    @Test
    void garbageSynchTimestampsPrintAsValidJson() throws IOException {
        CommandRun r = run("decode", trace("pioneer-laser-sonar.gt.trace.jsonl").toString());
        long synchs = r.json().stream().filter(o -> o.has("type") && o.get("type").getAsInt() == 5).count();
        assertTrue(synchs > 100, "SYNCH messages: " + synchs);
    }

    @Test
    void undecodablePayloadsPrintRawWithErrorAndStreamOffset(@TempDir Path dir) throws IOException {
        // a laser scan whose ranges count claims far more data than the payload holds
        byte[] msg = new byte[40 + 28];
        byte[] header = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 6, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0,
            0, 0, 0, 0, 0, 0, 0, 0, 28};
        System.arraycopy(header, 0, msg, 0, 40);
        msg[40 + 16 + 3] = (byte) 180;
        msg[40 + 20] = 0x3F;
        Path trace = dir.resolve("bad.trace.jsonl");
        Files.writeString(trace, "{\"format\":\"player-trace\",\"version\":1}\n"
                + "{\"t\":1.5,\"conn\":3,\"port\":6666,\"dir\":\"c2s\",\"data\":\"" + Base64.getEncoder().encodeToString(msg)
                + "\"}\n");
        CommandRun r = run("decode", trace.toString());
        assertEquals(0, r.code());
        JsonObject o = r.json().get(0);
        assertEquals(3, o.get("conn").getAsInt());
        assertEquals(28, o.get("size").getAsInt());
        assertEquals(Base64.getEncoder().encodeToString(java.util.Arrays.copyOfRange(msg, 40, 68)), o.get("body").getAsString());
        assertTrue(o.get("error").getAsString().contains("laser SCAN"), o.toString());
        assertEquals(40 + 20, o.get("offset").getAsInt());
        assertEquals(MessageHeader.read(new XdrReader(msg)).interf(), o.get("interf").getAsInt());
    }

    @Test
    void truncatedStreamsReportErrorWithOffset(@TempDir Path dir) throws IOException {
        Path trace = dir.resolve("cut.trace.jsonl");
        Files.writeString(trace, "{\"format\":\"player-trace\",\"version\":1}\n"
                + "{\"t\":0.1,\"conn\":1,\"port\":6665,\"dir\":\"s2c\",\"data\":\""
                + Base64.getEncoder().encodeToString("Player v.3.1.1-dev\0\0\0\0\0\0\0\0\0\0\0\0\0\0\1\2\3".getBytes())
                + "\"}\n");
        List<JsonObject> out = run("decode", trace.toString()).json();
        assertEquals("Player v.3.1.1-dev", out.get(0).get("ident").getAsString());
        assertEquals(32, out.get(1).get("offset").getAsInt());
        assertTrue(out.get(1).get("error").getAsString().contains("stream ended"));
    }

    @Test
    void unreadableFilesExitNonZeroWithAClearMessage(@TempDir Path dir) throws IOException {
        CommandRun missing = run("decode", dir.resolve("nope.jsonl").toString());
        assertEquals(ExitCode.FAILED, missing.code(), "a file that is not there is no usage error");
        assertTrue(missing.err().contains("nope.jsonl: no such file"), missing.err());

        Path bad = dir.resolve("bad.jsonl");
        Files.writeString(bad, "hello\n");
        CommandRun invalid = run("stats", bad.toString());
        assertEquals(1, invalid.code());
        assertTrue(invalid.err().contains("bad.jsonl:1:"), invalid.err());

        assertEquals(2, run("frobnicate").code());
        assertEquals(2, run().code());
    }

    @Test
    void statsCountsPerDirectionInterfaceTypeAndSubtype() {
        CommandRun r = run("stats", trace("requests.reqclient.trace.jsonl").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().lines().anyMatch(l -> l.matches("s2c\\s+player\\s+SYNCH\\s+OK\\s+69\\s+2760")), r.out());
        assertTrue(r.out().lines().anyMatch(l -> l.matches("s2c\\s+laser\\s+RESP_NACK\\s+SET_CONFIG\\s+2\\s+80")),
                "rangertolaser's double NACK is counted twice");
        assertTrue(r.out().contains("total: 1280 messages, 752084 bytes, 1 banners, 0 unframed bytes, 0 decode errors"),
                r.out());
    }
}
