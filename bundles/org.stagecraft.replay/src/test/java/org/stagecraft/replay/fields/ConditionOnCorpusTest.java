package org.stagecraft.replay.fields;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

import org.eclipse.jdt.annotation.Nullable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.spy.breakpoint.MessageCondition;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Robot data breakpoint conditions on every recorded trace: the messages a condition holds on — found
 * the way the spy finds them, from a header and payload bytes — are exactly those an independent count
 * finds, one written against the decoder's typed messages, and for the ground-truth traces one over what
 * libplayerc itself decoded.
 */
class ConditionOnCorpusTest {
    private static final CodecRegistry CODECS = CodecRegistry.standard();

    /** A condition and the same test written by hand against the typed message. */
    record Case(String text, Predicate<MessageBody> byHand) {
    }

    static final List<Case> CASES = List.of(
            new Case("laser:0 min(ranges) < 1.0", b -> b instanceof Laser.Scan s && min(s.ranges().toArray()) < 1.0f),
            new Case("laser:0 count(ranges) > 100 and max(ranges) >= 7.9", b -> b instanceof Laser.Scan s
                    && s.ranges().size() > 100 && max(s.ranges().toArray()) >= 7.9f),
            new Case("ranger:0 min(ranges) < 50 cm", b -> b instanceof Ranger.Values v && v.name().equals("ranges")
                    && v.values().size() > 0 && min(v.values().toArray()) < 0.5),
            new Case("ranger:1 ranges[90] < 2", b -> b instanceof Ranger.Values v && v.name().equals("ranges")
                    && v.values().size() > 90 && v.values().get(90) < 2),
            new Case("position2d:0 pos.px > 0 and stall == 0", b -> b instanceof Position2d.State s && s.pos().px() > 0
                    && s.stall() == 0),
            new Case("position2d:0 abs(vel.pa) > 10 deg/s or vel.px < -0.01 m/s", b -> b instanceof Position2d.State s
                    && (Math.abs(s.vel().pa()) > Math.toRadians(10) || s.vel().px() < -0.01)));

    static List<Path> traces() {
        return TraceCorpus.all();
    }

    private static float min(float[] a) {
        float m = Float.POSITIVE_INFINITY;
        for (float f : a) {
            m = Math.min(m, f);
        }
        return m;
    }

    private static int firstIndexOf(float[] a, float v) {
        for (int i = 0; i < a.length; i++) {
            if (a[i] == v) {
                return i;
            }
        }
        return -1;
    }

    private static float max(float[] a) {
        float m = Float.NEGATIVE_INFINITY;
        for (float f : a) {
            m = Math.max(m, f);
        }
        return m;
    }

    private static double min(double[] a) {
        double m = Double.POSITIVE_INFINITY;
        for (double d : a) {
            m = Math.min(m, d);
        }
        return m;
    }

    /**
     * Hits of each case on one trace: [by the condition, by hand], per case; connection 0 = all; only
     * messages stamped up to {@code untilTimestamp} (Player's header time).
     */
    private static long[][] count(Path trace, List<Case> cases, int onlyConnection, double untilTimestamp) throws IOException {
        List<StreamCondition> conditions = cases.stream().map(c -> StreamCondition.parse(c.text(), CODECS)).toList();
        long[][] hits = new long[cases.size()][2];
        try (SessionLog log = SessionLogs.open(trace, CODECS); LogCursor cur = log.cursor(Long.MIN_VALUE)) {
            for (LogMessage m = cur.next(); m != null; m = cur.next()) {
                if (m.kind() != LogMessage.Kind.FRAME || m.dir() != Direction.SERVER_TO_CLIENT
                        || onlyConnection != 0 && m.connection().id() != onlyConnection) {
                    continue;
                }
                byte[] wire = m.bytes();
                MessageHeader h = MessageHeader.read(wire, 0);
                if (h.timestamp() > untilTimestamp) {
                    continue;
                }
                byte[] payload = java.util.Arrays.copyOfRange(wire, MessageHeader.SIZE, wire.length);
                MessageBody body = m.decoded() == null ? null : m.decoded().body();
                for (int i = 0; i < cases.size(); i++) {
                    StreamCondition c = conditions.get(i);
                    MessageCondition.Satisfied hit = c.watches(m.connection(), h) ? c.test(h, payload) : null;
                    if (hit != null) {
                        hits[i][0]++;
                        if (body instanceof Laser.Scan scan && c.text().contains("min(ranges)")) {
                            // the beam a view marks is the nearest return, found by hand here
                            float[] r = scan.ranges().toArray();
                            assertEquals(List.of("ranges[" + firstIndexOf(r, min(r)) + "]"), hit.decidingFields(),
                                    trace.getFileName() + ": " + c.text());
                        }
                    }
                    if (body != null && c.watches(m.connection(), h) && cases.get(i).byHand().test(body)) {
                        hits[i][1]++;
                    }
                }
            }
        }
        return hits;
    }

    @ParameterizedTest
    @MethodSource("traces")
    void hitsEqualAnIndependentCount(Path trace) throws IOException {
        long[][] hits = count(trace, CASES, 0, Double.POSITIVE_INFINITY);
        for (int i = 0; i < CASES.size(); i++) {
            assertEquals(hits[i][1], hits[i][0], trace.getFileName() + ": " + CASES.get(i).text());
        }
    }

    /** The cases find something on the corpus: the equality above is not 0 = 0 everywhere. */
    @Test
    void everyCaseHoldsSomewhereAndFailsSomewhere() throws IOException {
        long[] found = new long[CASES.size()];
        for (Path t : traces()) {
            long[][] hits = count(t, CASES, 0, Double.POSITIVE_INFINITY);
            for (int i = 0; i < CASES.size(); i++) {
                found[i] += hits[i][0];
            }
        }
        for (int i = 0; i < CASES.size(); i++) {
            assertTrue(found[i] > 0, CASES.get(i).text() + " held on no message of the corpus");
        }
    }

    /** Against libplayerc: its decoded sonar ranges and odometry, line by line of the ground truth. */
    @ParameterizedTest
    @MethodSource("groundTruths")
    void hitsEqualWhatLibplayercDecoded(Path groundTruth) throws IOException {
        Path trace = groundTruth.resolveSibling(groundTruth.getFileName().toString().replace(".groundtruth.jsonl", ".trace.jsonl"));
        List<Case> sonar = List.of(new Case("ranger:0 min(ranges) < 1.0", b -> true));
        List<Case> odometry = List.of(new Case("position2d:0 pos.px > 0.5", b -> true), new Case("position2d:0 pos.pa < -0.2", b -> true));
        long sonarNear = 0;
        long east = 0;
        long turned = 0;
        long sonarLines = 0;
        long odometryLines = 0;
        // the client stopped logging before the recording ended: compare what it saw, per device
        double lastSonar = 0;
        double lastOdometry = 0;
        for (String line : Files.readAllLines(groundTruth)) {
            JsonObject o = JsonParser.parseString(line).getAsJsonObject();
            @Nullable JsonObject d = o.has("decoded") ? o.getAsJsonObject("decoded") : null;
            if (d == null || !o.has("iface")) {
                continue;
            }
            String iface = o.get("iface").getAsString();
            if (iface.equals("ranger(sonar)") && d.has("ranges")) {
                sonarLines++;
                lastSonar = Math.max(lastSonar, o.get("timestamp").getAsDouble());
                JsonArray r = d.getAsJsonArray("ranges");
                double m = Double.POSITIVE_INFINITY;
                for (var e : r) {
                    m = Math.min(m, e.getAsDouble());
                }
                sonarNear += m < 1.0 ? 1 : 0;
            } else if (iface.equals("position2d")) {
                odometryLines++;
                lastOdometry = Math.max(lastOdometry, o.get("timestamp").getAsDouble());
                east += d.get("px").getAsDouble() > 0.5 ? 1 : 0;
                turned += d.get("pa").getAsDouble() < -0.2 ? 1 : 0;
            }
        }
        assertTrue(sonarLines > 0 && odometryLines > 0, "ground truth without sonar or odometry lines: " + groundTruth);
        assertTrue(sonarNear > 0 && east > 0 && turned > 0, "the thresholds must pick some messages out: " + sonarNear + ", "
                + east + ", " + turned);
        assertEquals(sonarNear, count(trace, sonar, 1, lastSonar)[0][0], "sonar min < 1.0 m");
        long[][] hits = count(trace, odometry, 1, lastOdometry);
        assertEquals(east, hits[0][0], "pos.px > 0.5 m");
        assertEquals(turned, hits[1][0], "pos.pa < -0.2 rad");
    }

    static List<Path> groundTruths() throws IOException {
        List<Path> out = new ArrayList<>();
        try (var s = Files.list(TraceCorpus.dir())) {
            s.filter(p -> p.getFileName().toString().endsWith(".groundtruth.jsonl")).sorted().forEach(out::add);
        }
        assertTrue(!out.isEmpty(), "no ground truth in " + TraceCorpus.dir());
        return out;
    }
}
