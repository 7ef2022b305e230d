package org.stagecraft.foxglove.live;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveSink;

/** Which channels go when a connection ends, and how they come back. */
class LiveChannelsTest {
    private static final FoxgloveChannel SCAN = FoxgloveChannel.json("/robot6665/laser0/scan", "foxglove.LaserScan", "{}");
    private static final FoxgloveChannel OTHER = FoxgloveChannel.json("/robot6666/laser0/scan", "foxglove.LaserScan", "{}");

    /** The calls the server would get, as text. */
    private static final class Calls implements FoxgloveSink {
        final List<String> calls = new ArrayList<>();

        @Override
        public void advertise(FoxgloveChannel c) {
            calls.add("advertise " + c.topic());
        }

        @Override
        public void publish(FoxgloveChannel c, long log, long pub, byte[] json) {
            calls.add("publish " + c.topic());
        }

        @Override
        public void unadvertise(FoxgloveChannel c) {
            calls.add("unadvertise " + c.topic());
        }
    }

    @Test
    void aChannelGoesWithTheLastConnectionThatFedItAndComesBackWithItsNextMessage() {
        Calls server = new Calls();
        LiveChannels channels = new LiveChannels(server);
        channels.advertise(SCAN);
        channels.advertise(OTHER);
        channels.converting(1);
        channels.publish(SCAN, 1, 1, new byte[0]);
        channels.converting(2);
        channels.publish(SCAN, 2, 2, new byte[0]); // a second program reading the same laser
        channels.converting(3);
        channels.publish(OTHER, 3, 3, new byte[0]);
        server.calls.clear();

        channels.connectionEnded(1);
        assertEquals(List.of(), server.calls, "connection 2 still feeds the scan");
        channels.connectionEnded(2);
        assertEquals(List.of("unadvertise /robot6665/laser0/scan"), server.calls);
        channels.connectionEnded(2);
        assertEquals(1, server.calls.size(), "told once");

        server.calls.clear();
        channels.converting(4); // the robot program reconnects
        channels.publish(SCAN, 4, 4, new byte[0]);
        assertEquals(List.of("advertise /robot6665/laser0/scan", "publish /robot6665/laser0/scan"), server.calls);
        server.calls.clear();
        channels.connectionEnded(4);
        assertEquals(List.of("unadvertise /robot6665/laser0/scan"), server.calls);
    }

    @Test
    void messagesOfNoConnectionKeepTheirChannel() {
        Calls server = new Calls();
        LiveChannels channels = new LiveChannels(server);
        channels.advertise(SCAN);
        channels.converting(LiveChannels.NO_CONNECTION);
        channels.publish(SCAN, 1, 1, new byte[0]);
        channels.connectionEnded(1);
        assertEquals(List.of("advertise /robot6665/laser0/scan", "publish /robot6665/laser0/scan"), server.calls);
    }
}
