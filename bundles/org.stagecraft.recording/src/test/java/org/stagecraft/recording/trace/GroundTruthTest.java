package org.stagecraft.recording.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.msg.DoubleArray;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.wire.WireEvent;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Compares every DATA message the client received with what Player's own client library
 * (libplayerc) decoded from it, value by value, exactly. libplayerc keeps per-device state (a
 * ranger proxy remembers the last intensity count and the geometry), which the comparison models
 * the way libplayerc does.
 */
class GroundTruthTest {
    private static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());

    /** What libplayerc remembers per ranger device between messages. */
    private static final class RangerState {
        long rangesCount;
        long intensitiesCount;
        long elementCount;
    }

    @ParameterizedTest
    @ValueSource(strings = {"pioneer-laser-sonar.gt", "rates.headless-push"})
    void everyDataMessageMatchesLibplayerc(String scenario) throws IOException {
        List<DecodedMessage> received = dispatchOrder(scenario);
        Map<Integer, RangerState> rangers = new HashMap<>();

        List<JsonObject> truth = new ArrayList<>();
        try (BufferedReader in = Files.newBufferedReader(TraceCorpus.file(scenario + ".groundtruth.jsonl"),
                StandardCharsets.UTF_8)) {
            in.readLine();
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                JsonObject o = JsonParser.parseString(line).getAsJsonObject();
                if (o.has("decoded")) {
                    truth.add(o);
                }
            }
        }

        int next = 0;
        int compared = 0;
        int[] laserIntensityOn = {0};
        for (JsonObject gt : truth) {
            DecodedMessage m;
            while (true) {
                assertTrue(next < received.size(), "trace ended before ground-truth line " + gt);
                m = received.get(next++);
                if (m.header().messageType() == MessageType.DATA) {
                    break;
                }
                if (m.body() instanceof Ranger.Geom g) {
                    rangers.computeIfAbsent(m.header().index(), k -> new RangerState()).elementCount = g.elementPoses().size();
                } else if (m.body() instanceof Laser.Config c) {
                    laserIntensityOn[0] = c.intensity();
                }
            }
            String where = scenario + " ground truth #" + compared + " " + gt.get("iface").getAsString() + " t="
                    + gt.get("t");
            compareHeader(gt, m.header(), where);
            JsonObject d = gt.getAsJsonObject("decoded");
            switch (m.body()) {
                case Position2d.State s -> comparePosition(d, s, where);
                case Laser.Scan s -> compareLaser(d, s, laserIntensityOn[0], where);
                case Ranger.Values v -> compareRanger(d, v, m.header(),
                        rangers.computeIfAbsent(m.header().index(), k -> new RangerState()), where);
                default -> throw new AssertionError(where + ": unexpected body " + m.body());
            }
            compared++;
        }
        assertEquals(truth.size(), compared);
        long leftover = received.subList(next, received.size()).stream()
                .filter(m -> m.header().messageType() == MessageType.DATA).count();
        // Matching is strictly in order, so the only unmatched messages are those that arrived after
        // the client's last read (in PUSH mode the server keeps sending until the socket closes).
        assertTrue(leftover < compared / 50, "DATA messages never dispatched by libplayerc: " + leftover);
        assertTrue(compared > 2000, "compared " + compared);
    }

    /**
     * The order in which libplayerc hands messages to its proxies: while a request waits for its
     * reply, DATA that arrives meanwhile is queued and dispatched after the reply
     * (playerc_client_request pushes it onto the client's queue).
     */
    private static List<DecodedMessage> dispatchOrder(String scenario) throws IOException {
        List<DecodedMessage> dispatched = new ArrayList<>();
        List<DecodedMessage> queued = new ArrayList<>();
        boolean[] waiting = {false};
        TraceFraming.frame(TraceCorpus.file(scenario + ".trace.jsonl"), e -> {
            if (!(e.event() instanceof WireEvent.Frame f)) {
                return;
            }
            DecodedMessage m = DECODER.decode(f);
            MessageType type = m.header().messageType();
            if (e.stream().dir() == Direction.CLIENT_TO_SERVER) {
                waiting[0] |= type == MessageType.REQ;
                return;
            }
            if (type == MessageType.DATA) {
                (waiting[0] ? queued : dispatched).add(m);
            } else if (type == MessageType.RESP_ACK || type == MessageType.RESP_NACK) {
                if (m.body() instanceof Ranger.Geom || m.body() instanceof Laser.Config) {
                    dispatched.add(m); // replies whose values libplayerc's proxies remember
                }
                waiting[0] = false;
                dispatched.addAll(queued);
                queued.clear();
            }
        });
        dispatched.addAll(queued);
        return dispatched;
    }

    private static void compareHeader(JsonObject gt, MessageHeader h, String where) {
        assertEquals(gt.get("host").getAsLong(), h.hostUnsigned(), where + " host");
        assertEquals(gt.get("robot").getAsLong(), h.robotUnsigned(), where + " robot");
        assertEquals(gt.get("interf").getAsInt(), h.interf(), where + " interf");
        assertEquals(gt.get("index").getAsInt(), h.index(), where + " index");
        assertEquals(gt.get("type").getAsInt(), h.type(), where + " type");
        assertEquals(gt.get("subtype").getAsInt(), h.subtype(), where + " subtype");
        assertEquals(gt.get("timestamp").getAsDouble(), h.timestamp(), where + " timestamp");
        assertEquals(gt.get("seq").getAsLong(), h.seqUnsigned(), where + " seq");
    }

    private static void comparePosition(JsonObject d, Position2d.State s, String where) {
        assertEquals(d.get("px").getAsDouble(), s.pos().px(), where + " px");
        assertEquals(d.get("py").getAsDouble(), s.pos().py(), where + " py");
        assertEquals(d.get("pa").getAsDouble(), s.pos().pa(), where + " pa");
        assertEquals(d.get("vx").getAsDouble(), s.vel().px(), where + " vx");
        assertEquals(d.get("vy").getAsDouble(), s.vel().py(), where + " vy");
        assertEquals(d.get("va").getAsDouble(), s.vel().pa(), where + " va");
        assertEquals(d.get("stall").getAsInt(), s.stall(), where + " stall");
    }

    private static void compareLaser(JsonObject d, Laser.Scan s, int intensityOn, String where) {
        // libplayerc widens the floats to double; the ground truth prints them with float precision.
        assertEquals(d.get("scan_count").getAsLong(), s.ranges().size(), where + " scan_count");
        assertEquals(Integer.toUnsignedLong(s.rangesCount()), s.ranges().size(), where + " ranges_count");
        assertEquals(d.get("scan_start").getAsFloat(), s.minAngle(), where + " scan_start");
        assertEquals(d.get("scan_res").getAsFloat(), s.resolution(), where + " scan_res");
        assertEquals(d.get("max_range").getAsFloat(), s.maxRange(), where + " max_range");
        assertEquals(d.get("scan_id").getAsLong(), Integer.toUnsignedLong(s.id()), where + " scan_id");
        // libplayerc takes intensity_on from the last configuration reply, not from the scan
        assertEquals(d.get("intensity_on").getAsInt(), intensityOn, where + " intensity_on");
        FloatArray r = s.ranges();
        double min = Double.POSITIVE_INFINITY;
        for (int i = 0; i < r.size(); i++) {
            min = Math.min(min, r.get(i));
        }
        assertEquals(d.get("min_range").getAsDouble(), min, where + " min_range");
        JsonArray first3 = d.getAsJsonArray("first3");
        for (int i = 0; i < first3.size(); i++) {
            assertEquals(first3.get(i).getAsDouble(), (double) r.get(i), where + " ranges[" + i + "]");
        }
    }

    private static void compareRanger(JsonObject d, Ranger.Values v, MessageHeader h, RangerState state, String where) {
        DoubleArray values = v.values();
        if (h.subtype() == 1) {
            state.rangesCount = values.size();
        } else {
            state.intensitiesCount = values.size();
        }
        assertEquals(d.get("ranges_count").getAsLong(), state.rangesCount, where + " ranges_count");
        assertEquals(d.get("intensities_count").getAsLong(), state.intensitiesCount, where + " intensities_count");
        assertEquals(d.get("element_count").getAsLong(), state.elementCount, where + " element_count");
        if (h.subtype() == 1) {
            double min = Double.POSITIVE_INFINITY;
            for (int i = 0; i < values.size(); i++) {
                min = Math.min(min, values.get(i));
            }
            assertEquals(d.get("min_range").getAsDouble(), min, where + " min_range");
            JsonArray first3 = d.getAsJsonArray("first3");
            for (int i = 0; i < first3.size(); i++) {
                assertEquals(first3.get(i).getAsDouble(), values.get(i), where + " ranges[" + i + "]");
            }
            if (d.has("ranges")) {
                JsonArray all = d.getAsJsonArray("ranges");
                assertEquals(all.size(), values.size(), where + " ranges length");
                for (int i = 0; i < all.size(); i++) {
                    assertEquals(all.get(i).getAsDouble(), values.get(i), where + " ranges[" + i + "]");
                }
            }
        } else {
            JsonArray first3 = d.getAsJsonArray("first3_intensities");
            for (int i = 0; i < first3.size(); i++) {
                assertEquals(first3.get(i).getAsDouble(), values.get(i), where + " intensities[" + i + "]");
            }
        }
    }
}
