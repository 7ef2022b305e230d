package org.stagecraft.foxglove.live;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.EmptyBody;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamMessage;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** Player's own channels, live: the export's topics and JSON, and a schema that grows with new layouts. */
class PlayerChannelsTest {
    private static final ConnectionInfo C = new ConnectionInfo(3, 6665, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");

    private static final class Calls implements FoxgloveSink {
        final List<String> calls = new ArrayList<>();
        final List<FoxgloveChannel> advertised = new ArrayList<>();
        final List<byte[]> published = new ArrayList<>();

        @Override
        public void advertise(FoxgloveChannel c) {
            calls.add("advertise " + c.topic());
            advertised.add(c);
        }

        @Override
        public void publish(FoxgloveChannel c, long log, long pub, byte[] json) {
            calls.add("publish " + c.topic());
            published.add(json);
        }

        @Override
        public void unadvertise(FoxgloveChannel c) {
            calls.add("unadvertise " + c.topic());
        }
    }

    private static StreamMessage message(int type, int subtype, MessageBody body) {
        MessageHeader h = new MessageHeader(0, 0, Laser.CODE, 0, type, subtype, 12.5, 0, 0);
        return new StreamMessage(SpyStreams.messageKey(C, Direction.SERVER_TO_CLIENT, h), 1_795_315_969_000_000_000L,
                new SpyMessage(C, Direction.SERVER_TO_CLIENT, 0, new DecodedMessage(h, body, null)));
    }

    @Test
    void aLaserScanGoesOnTheExportsTopicAsPlayersJson() {
        Calls sink = new Calls();
        PlayerChannels p = new PlayerChannels(sink, CodecRegistry.standard());
        Laser.Scan scan = new Laser.Scan(-1, 1, 1, 8, 3, FloatArray.of(1, 2, 3), 0, ByteArray.EMPTY, 7);
        p.accept(message(1, 1, scan));
        p.accept(message(1, 1, scan));
        assertEquals(List.of("advertise /6665/3/laser:0/DATA/SCAN", "publish /6665/3/laser:0/DATA/SCAN",
                "publish /6665/3/laser:0/DATA/SCAN"), sink.calls);
        FoxgloveChannel c = sink.advertised.get(0);
        assertEquals("player.laser.DATA.SCAN", c.schemaName());
        assertEquals("json", c.messageEncoding());
        assertEquals("jsonschema", c.schemaEncoding());
        assertTrue(c.schema().contains("\"ranges\""), c.schema());
        JsonObject json = JsonParser.parseString(new String(sink.published.get(0), StandardCharsets.UTF_8)).getAsJsonObject();
        assertEquals(3, json.getAsJsonArray("ranges").size());
        assertEquals(12.5, json.getAsJsonObject("header").get("timestamp").getAsDouble());
    }

    @Test
    void aNewLayoutOnAStreamAdvertisesItsChannelAgainWithTheMergedSchema() {
        Calls sink = new Calls();
        PlayerChannels p = new PlayerChannels(sink, CodecRegistry.standard());
        Laser.Scan scan = new Laser.Scan(-1, 1, 1, 8, 3, FloatArray.of(1, 2, 3), 0, ByteArray.EMPTY, 7);
        p.accept(message(6, 1, EmptyBody.INSTANCE)); // a NACK without a body
        p.accept(message(6, 1, scan)); // the same stream, now with one
        p.accept(message(6, 1, EmptyBody.INSTANCE)); // covered by the merged schema: no change
        String topic = sink.calls.get(0).substring("advertise ".length());
        assertEquals(List.of("advertise " + topic, "publish " + topic, "unadvertise " + topic, "advertise " + topic,
                "publish " + topic, "publish " + topic), sink.calls);
        assertTrue(!sink.advertised.get(0).schema().contains("\"ranges\"") && sink.advertised.get(1).schema().contains("\"ranges\""),
                "the second schema has the new members");
    }
}
