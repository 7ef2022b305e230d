package org.stagecraft.recording.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.msg.Geometry.DevAddr;
import org.stagecraft.player.msg.Geometry.DeviceGeom;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.PlayerDevice;
import org.stagecraft.player.msg.Ranger;
import org.stagecraft.player.msg.Simulation;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.player.wire.WireEvent;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;

/** Replies of the requests scenario, decoded, against the values libplayerc reported per step. */
class RequestRepliesTest {
    private static final List<DecodedMessage> REPLIES = new ArrayList<>();
    private static final List<JsonObject> STEPS = new ArrayList<>();

    @BeforeAll
    static void load() throws IOException {
        PlayerDecoder decoder = new PlayerDecoder(CodecRegistry.standard());
        TraceFraming.frame(TraceCorpus.file("requests.reqclient.trace.jsonl"), e -> {
            if (e.stream().dir() == Direction.SERVER_TO_CLIENT && e.event() instanceof WireEvent.Frame f) {
                MessageType t = f.header().messageType();
                if (t == MessageType.RESP_ACK || t == MessageType.RESP_NACK) {
                    REPLIES.add(decoder.decode(f));
                }
            }
        });
        try (BufferedReader in = Files.newBufferedReader(TraceCorpus.file("requests.reqclient.steps.jsonl"),
                StandardCharsets.UTF_8)) {
            in.readLine();
            for (String l = in.readLine(); l != null; l = in.readLine()) {
                try {
                    STEPS.add(JsonParser.parseString(l).getAsJsonObject());
                } catch (JsonParseException e) {
                    // two property steps quote a key inside the step text without escaping; they carry no values
                    assertTrue(l.contains("PROP \""), "unexpected unparseable step: " + l);
                }
            }
        }
    }

    private static JsonObject step(String prefix) {
        return STEPS.stream().filter(s -> s.get("step").getAsString().startsWith(prefix)).findFirst().orElseThrow();
    }

    private static List<DecodedMessage> replies(int interf, int index, MessageType type, int subtype) {
        return REPLIES.stream().filter(m -> m.header().interf() == interf && m.header().index() == index
                && m.header().messageType() == type && m.header().subtype() == subtype).toList();
    }

    private static DecodedMessage ack(int interf, int index, int subtype) {
        return replies(interf, index, MessageType.RESP_ACK, subtype).get(0);
    }

    @Test
    void deviceListAndDriverNames() {
        JsonArray devices = step("get_devlist").getAsJsonArray("devices");
        PlayerDevice.DevList list = (PlayerDevice.DevList) ack(1, 0, 1).body();
        assertEquals(devices.size(), list.devices().size());
        List<DecodedMessage> infos = replies(1, 0, MessageType.RESP_ACK, 2);
        for (int i = 0; i < devices.size(); i++) {
            JsonArray d = devices.get(i).getAsJsonArray();
            DevAddr a = list.devices().get(i);
            assertEquals(d.get(0).getAsLong(), Integer.toUnsignedLong(a.host()));
            assertEquals(d.get(1).getAsInt(), a.robot());
            assertEquals(d.get(2).getAsInt(), a.interf());
            assertEquals(d.get(3).getAsInt(), a.index());
            assertEquals(d.get(4).getAsString(), ((PlayerDevice.DriverInfo) infos.get(i).body()).driverName().text());
        }
    }

    @Test
    void subscribingAMissingDeviceIsANackWithAccessError() {
        DecodedMessage nack = replies(1, 0, MessageType.RESP_NACK, 3).get(0);
        PlayerDevice.DeviceReq req = assertInstanceOf(PlayerDevice.DeviceReq.class, nack.body());
        assertEquals(PlayerDevice.ACCESS_ERROR, req.access());
        assertEquals(5, req.addr().interf(), "sonar:0 does not exist in this world");
    }

    @Test
    void geometries() {
        JsonObject p = step("position2d GET_GEOM");
        DeviceGeom g = (DeviceGeom) ack(4, 0, 1).body();
        assertEquals(p.getAsJsonArray("pose").get(0).getAsDouble(), g.pose().px());
        assertEquals(p.getAsJsonArray("pose").get(1).getAsDouble(), g.pose().py());
        assertEquals(p.getAsJsonArray("pose").get(2).getAsDouble(), g.pose().pyaw());
        // libplayerc's position2d proxy stores size as {length, width} = {sl, sw}
        assertEquals(p.getAsJsonArray("size").get(0).getAsDouble(), g.size().sl());
        assertEquals(p.getAsJsonArray("size").get(1).getAsDouble(), g.size().sw());
        Ranger.Geom sonar = (Ranger.Geom) ack(62, 0, 1).body();
        assertEquals(step("ranger:0 GET_GEOM").get("element_count").getAsInt(), sonar.elementPoses().size());
    }

    @Test
    void configurations() {
        JsonObject l = step("laser GET_CONFIG");
        Laser.Config c = (Laser.Config) ack(6, 0, 3).body();
        assertEquals(l.get("min_angle").getAsFloat(), c.minAngle());
        assertEquals(l.get("max_angle").getAsFloat(), c.maxAngle());
        assertEquals(l.get("resolution").getAsFloat(), c.resolution());
        assertEquals(l.get("range_res").getAsFloat(), c.rangeRes());
        assertEquals(l.get("intensity").getAsInt(), c.intensity());
        assertEquals(l.get("scanning_frequency").getAsFloat(), c.scanningFrequency());
        JsonObject r = step("ranger:0 GET_CONFIG");
        Ranger.Config rc = (Ranger.Config) ack(62, 0, 5).body();
        assertEquals(r.get("min_angle").getAsDouble(), rc.minAngle());
        assertEquals(r.get("max_angle").getAsDouble(), rc.maxAngle());
        assertEquals(r.get("angular_res").getAsDouble(), rc.angularRes());
        assertEquals(r.get("min_range").getAsDouble(), rc.minRange());
        assertEquals(r.get("max_range").getAsDouble(), rc.maxRange());
        assertEquals(r.get("range_res").getAsDouble(), rc.rangeRes());
        assertEquals(r.get("frequency").getAsDouble(), rc.frequency());
    }

    @Test
    void laserSetConfigIsAnsweredByTwoNacks() {
        JsonArray stray = step("drain").getAsJsonArray("stray_replies").get(0).getAsJsonArray();
        List<DecodedMessage> nacks = replies(stray.get(0).getAsInt(), stray.get(1).getAsInt(),
                MessageType.of(stray.get(2).getAsInt()), stray.get(3).getAsInt());
        assertEquals(2, nacks.size());
    }

    @Test
    void simulationPosesAndProperties() {
        List<DecodedMessage> poses = replies(31, 0, MessageType.RESP_ACK, 1);
        JsonArray first = step("simulation GET_POSE2D r0").getAsJsonArray("pose");
        JsonArray again = step("simulation GET_POSE2D r0 again").getAsJsonArray("pose");
        Simulation.PoseReq2d p0 = (Simulation.PoseReq2d) poses.get(0).body();
        Simulation.PoseReq2d p1 = (Simulation.PoseReq2d) poses.get(1).body();
        assertEquals("r0", p0.name().text());
        assertEquals(first.get(0).getAsDouble(), p0.pose().px());
        assertEquals(first.get(1).getAsDouble(), p0.pose().py());
        assertEquals(first.get(2).getAsDouble(), p0.pose().pa());
        assertEquals(again.get(2).getAsDouble(), p1.pose().pa());

        Simulation.PropertyReq color = (Simulation.PropertyReq) ack(31, 0, 5).body();
        assertEquals("color", color.prop().text());
        // raw host memory of the little-endian simulator: four floats
        ByteBuffer v = ByteBuffer.wrap(color.value().toArray()).order(ByteOrder.LITTLE_ENDIAN);
        JsonArray rgba = step("simulation GET_PROPERTY r0 color").getAsJsonArray("rgba");
        for (int i = 0; i < 4; i++) {
            assertEquals(rgba.get(i).getAsFloat(), v.getFloat(), "rgba[" + i + "]");
        }
    }
}
