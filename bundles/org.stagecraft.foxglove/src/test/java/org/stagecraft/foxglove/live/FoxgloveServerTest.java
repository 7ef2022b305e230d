package org.stagecraft.foxglove.live;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.java_websocket.protocols.IProtocol;
import org.java_websocket.protocols.Protocol;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.foxglove.FoxgloveChannel;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;

/** The live server against a real WebSocket client (Java-WebSocket's), on loopback, port 0. */
class FoxgloveServerTest {
    private static final String LOG_SCHEMA = "{\"type\":\"object\",\"properties\":{\"message\":{\"type\":\"string\"}}}";
    private static final FoxgloveChannel LOG = FoxgloveChannel.json("/stagecraft/log", "foxglove.Log", LOG_SCHEMA);
    private static final FoxgloveChannel SCAN = FoxgloveChannel.json("/robot6665/laser0/scan", "foxglove.LaserScan",
            "{\"type\":\"object\"}");
    private static final long T0 = 1_764_000_000_000_000_000L; // an epoch time in ns (Nov 2025)

    private final List<AutoCloseable> open = new ArrayList<>();

    private FoxgloveServer server(int maxQueuedFrames) throws IOException {
        FoxgloveServer s = FoxgloveServer.start(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), "test",
                maxQueuedFrames);
        open.add(s);
        return s;
    }

    private TestViewer viewer(FoxgloveServer s) throws InterruptedException {
        TestViewer v = TestViewer.connected(s);
        open.add(v::closeBlocking);
        return v;
    }

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
    }

    /**
     * Subscriptions are made on the server's thread: publishes probe messages until every viewer has
     * received one (each viewer's probe frames are taken out of its queue).
     *
     * @return the number of probes published
     */
    private static int awaitSubscribed(FoxgloveServer s, FoxgloveChannel channel, TestViewer... viewers)
            throws InterruptedException {
        boolean[] got = new boolean[viewers.length];
        int n = 0;
        while (true) {
            boolean all = true;
            for (int i = 0; i < viewers.length; i++) {
                while (viewers[i].frames.poll() != null) {
                    got[i] = true;
                }
                all &= got[i];
            }
            if (all) {
                return n;
            }
            assertTrue(n < 10_000, "subscriptions not in effect after 10 000 probes");
            s.publish(channel, T0, T0, json("{\"probe\":" + n++ + "}"));
            if (viewers[0].frames.poll(10, TimeUnit.MILLISECONDS) != null) { // waits for the first viewer's frame
                got[0] = true;
            }
        }
    }

    /**
     * The server counts a viewer once it has queued its serverInfo and advertise, so a viewer can
     * read both before it is counted: polls (1 ms apart) until it is, for at most 10 s.
     */
    private static void awaitViewers(FoxgloveServer s, int n) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (s.counters().viewers() != n) {
            assertTrue(System.nanoTime() < end, "the server counts " + s.counters().viewers() + " viewers, not " + n);
            Thread.sleep(1);
        }
    }

    private static byte[] json(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    @Test
    void handshakeSelectsTheSubprotocolThenServerInfoThenAdvertise() throws Exception {
        FoxgloveServer s = server(16);
        assertTrue(s.uri().toString().matches("ws://127\\.0\\.0\\.1:\\d+"), s.uri().toString());
        assertTrue(s.address().getPort() > 0);
        s.advertise(LOG);
        TestViewer v = viewer(s);
        assertEquals("foxglove.websocket.v1", v.selectedProtocol);
        JsonObject info = v.nextText("serverInfo");
        assertEquals("test", info.get("name").getAsString());
        assertTrue(info.getAsJsonArray("capabilities").toString().contains("\"time\""), info.toString());
        assertFalse(info.get("sessionId").getAsString().isEmpty());
        JsonArray channels = v.nextText("advertise").getAsJsonArray("channels");
        assertEquals(1, channels.size());
        JsonObject c = channels.get(0).getAsJsonObject();
        assertEquals("/stagecraft/log", c.get("topic").getAsString());
        assertEquals("json", c.get("encoding").getAsString());
        assertEquals("foxglove.Log", c.get("schemaName").getAsString());
        assertEquals("jsonschema", c.get("schemaEncoding").getAsString());
        assertEquals(LOG_SCHEMA, c.get("schema").getAsString());
        awaitViewers(s, 1);
    }

    @Test
    void aNewViewerIsToldAnEmptyAdvertiseWhenThereIsNoChannelYet() throws Exception {
        TestViewer v = viewer(server(16));
        v.nextText("serverInfo");
        assertEquals(0, v.nextText("advertise").getAsJsonArray("channels").size());
    }

    @Test
    void aClientWithoutTheSubprotocolIsRefused() throws Exception {
        FoxgloveServer s = server(16);
        TestViewer plain = new TestViewer(s.uri(), List.<IProtocol>of(new Protocol("")));
        open.add(plain::closeBlocking);
        assertFalse(plain.connectBlocking(10, TimeUnit.SECONDS), "connected without foxglove.websocket.v1");
        assertEquals(0, s.counters().viewers());
    }

    @Test
    void aSubscriberGetsMessageFramesOfItsChannelsOnly() throws Exception {
        FoxgloveServer s = server(16);
        s.advertise(LOG);
        s.advertise(SCAN);
        TestViewer v = viewer(s);
        v.nextText("serverInfo");
        JsonArray channels = v.nextText("advertise").getAsJsonArray("channels");
        int scanId = -1;
        for (var c : channels) {
            if (c.getAsJsonObject().get("topic").getAsString().equals(SCAN.topic())) {
                scanId = c.getAsJsonObject().get("id").getAsInt();
            }
        }
        assertTrue(scanId >= 0, "no id for the scan channel in " + channels);
        v.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":7,\"channelId\":" + scanId + "}]}");
        // The subscription is made on the server's thread: publish until it takes effect (the log
        // channel, published first each round, must never arrive).
        TestViewer.Frame f = null;
        for (int i = 0; i < 1000 && f == null; i++) {
            s.publish(LOG, T0 + i, T0 + i, json("{\"message\":\"not subscribed\"}"));
            s.publish(SCAN, T0 + i, T0 + i, json("{\"ranges\":[" + i + "]}"));
            f = v.frames.poll(10, TimeUnit.MILLISECONDS);
        }
        assertTrue(f != null, "no frame after subscribing");
        assertEquals(7, f.subscriptionId());
        String payload = new String(f.payload(), StandardCharsets.UTF_8);
        assertTrue(payload.startsWith("{\"ranges\":["), payload);
        int i = Integer.parseInt(payload.replaceAll("\\D", ""));
        assertEquals(T0 + i, f.logTimeNanos());
        // a second later: the viewers' clock moves on (a time message) before the message comes
        long t1 = T0 + 1_000_000_000L;
        s.publish(SCAN, t1, t1, json("{\"ranges\":[5000]}"));
        TestViewer.Frame next;
        do {
            next = v.nextFrame();
            assertEquals(7, next.subscriptionId(), "a frame of another subscription");
        } while (next.logTimeNanos() != t1);
        assertArrayEquals(json("{\"ranges\":[5000]}"), next.payload());
        assertTrue(v.times.contains(t1), "no time message for " + t1 + ": " + v.times);
    }

    @Test
    void unadvertiseTellsViewersEndsSubscriptionsAndKeepsTheIdForTheSameChannel() throws Exception {
        FoxgloveServer s = server(16);
        s.advertise(SCAN);
        TestViewer v = viewer(s);
        v.nextText("serverInfo");
        int id = v.nextText("advertise").getAsJsonArray("channels").get(0).getAsJsonObject().get("id").getAsInt();
        v.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":" + id + "}]}");
        awaitSubscribed(s, SCAN, v);
        s.unadvertise(SCAN);
        JsonObject un = v.nextText("unadvertise");
        assertEquals("[" + id + "]", un.getAsJsonArray("channelIds").toString());
        assertEquals(0, s.counters().channels());
        assertThrows(IllegalStateException.class, () -> s.publish(SCAN, T0, T0, json("{}")));
        s.advertise(SCAN);
        JsonObject again = v.nextText("advertise");
        assertEquals(id, again.getAsJsonArray("channels").get(0).getAsJsonObject().get("id").getAsInt());
        // the old subscription went with the channel: subscribing anew with the same ids is accepted
        v.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":" + id + "}]}");
        v.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":" + id + "}]}");
        JsonObject refused = v.nextText("status");
        assertEquals(2, refused.get("level").getAsInt());
        assertTrue(refused.get("message").getAsString().contains("already"), refused.toString());
    }

    @Test
    void badRequestsGetAnErrorStatusNamingTheProblem() throws Exception {
        List<String> notices = new ArrayList<>();
        FoxgloveServer s = server(16);
        s.onNotice(n -> {
            synchronized (notices) {
                notices.add(n);
            }
        });
        TestViewer v = viewer(s);
        v.nextText("serverInfo");
        v.nextText("advertise");
        v.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":99}]}");
        JsonObject st = v.nextText("status");
        assertEquals(2, st.get("level").getAsInt());
        assertEquals("subscribe: no channel 99", st.get("message").getAsString());
        v.send("not json");
        assertTrue(v.nextText("status").get("message").getAsString().startsWith("bad request: not JSON"));
        v.send("{\"op\":\"getParameters\",\"parameterNames\":[]}");
        assertTrue(v.nextText("status").get("message").getAsString().contains("'getParameters' is not supported"));
        v.send("{\"op\":\"unsubscribe\",\"subscriptionIds\":[-1]}");
        assertTrue(v.nextText("status").get("message").getAsString().contains("is not a uint32"));
        synchronized (notices) {
            assertTrue(notices.stream().anyMatch(n -> n.endsWith("subscribe: no channel 99")), notices.toString());
        }
    }

    /**
     * A viewer that stopped reading (frozen, or its host gone without a FIN) with the server's buffers
     * to it full cannot be sent the close frame, so it never answers the closing handshake: its
     * connection is still cut when the server closes. Before, its socket stayed open after the server
     * had stopped, for as long as the viewer lived. The viewer is a plain socket that does the opening
     * handshake and the subscription by hand, then stops reading; once the server has closed it reads
     * again and must reach the end of the stream.
     */
    @Test
    void closingCutsAStuckViewerThatCannotBeToldItIsClosed() throws Exception {
        FoxgloveServer s = server(8);
        s.advertise(SCAN);
        try (java.net.Socket raw = new java.net.Socket(s.address().getAddress(), s.address().getPort())) {
            raw.setSoTimeout(10_000);
            java.io.OutputStream out = raw.getOutputStream();
            out.write(("GET / HTTP/1.1\r\nHost: " + s.address().getHostString() + ":" + s.address().getPort()
                    + "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: c3RhZ2VjcmFmdCB0ZXN0ICE=\r\n"
                    + "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n")
                    .getBytes(StandardCharsets.US_ASCII));
            java.io.DataInputStream in = new java.io.DataInputStream(raw.getInputStream());
            StringBuilder head = new StringBuilder();
            while (!head.toString().endsWith("\r\n\r\n")) {
                head.append((char) in.readUnsignedByte());
            }
            assertTrue(head.toString().startsWith("HTTP/1.1 101"), head.toString());
            assertEquals(0x1, readFrame(in).opcode(), "serverInfo");
            RawFrame advertise = readFrame(in);
            int channel = com.google.gson.JsonParser.parseString(new String(advertise.payload(), StandardCharsets.UTF_8))
                    .getAsJsonObject().getAsJsonArray("channels").get(0).getAsJsonObject().get("id").getAsInt();
            writeMaskedText(out, "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":" + channel + "}]}");
            int n = 0;
            do { // probes until the subscription is in effect: a message frame arrives
                assertTrue(n < 10_000, "subscription not in effect after 10 000 probes");
                s.publish(SCAN, T0, T0, json("{\"probe\":" + n++ + "}"));
            } while (readFrame(in).opcode() != 0x2);
            // now it stops reading: publish until its queue behind the full socket buffers overflows
            byte[] big = new byte[256 * 1024];
            while (s.counters().framesDropped() == 0) {
                assertTrue(n < 10_000, "nothing dropped after 10 000 messages to a viewer that does not read");
                s.publish(SCAN, T0 + n, T0 + n, big);
                n++;
            }

            long start = System.nanoTime();
            s.close();
            long closeMillis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
            assertTrue(closeMillis < 5_000, "close took " + closeMillis + " ms");
            assertEquals(0, s.counters().viewers());
            long frames = 0;
            while (readFrame(in).opcode() != -1) { // a SocketTimeoutException here: the connection was left open
                frames++;
            }
            System.out.printf("stuck viewer cut by close after %d ms; it then read %d frames and the end%n", closeMillis,
                    frames);
        }
    }

    /** Writes one masked text frame, as a client must (the key is fixed: nothing here needs it random). */
    private static void writeMaskedText(java.io.OutputStream out, String text) throws IOException {
        byte[] payload = text.getBytes(StandardCharsets.UTF_8);
        assertTrue(payload.length < 126, "short frames only");
        byte[] key = {0x12, 0x34, 0x56, 0x78};
        byte[] frame = new byte[2 + 4 + payload.length];
        frame[0] = (byte) 0x81;
        frame[1] = (byte) (0x80 | payload.length);
        System.arraycopy(key, 0, frame, 2, 4);
        for (int i = 0; i < payload.length; i++) {
            frame[6 + i] = (byte) (payload[i] ^ key[i % 4]);
        }
        out.write(frame);
        out.flush();
    }

    /** One frame from the server, read by hand; opcode -1 is the end of the stream. */
    private record RawFrame(int opcode, byte[] payload) {
    }

    /** Reads one (unmasked, unfragmented) frame from the server. */
    private static RawFrame readFrame(java.io.DataInputStream in) throws IOException {
        int b0 = in.read();
        if (b0 == -1) {
            return new RawFrame(-1, new byte[0]);
        }
        int len = in.readUnsignedByte() & 0x7F;
        long n = len == 126 ? in.readUnsignedShort() : len == 127 ? in.readLong() : len;
        return new RawFrame(b0 & 0x0F, in.readNBytes(Math.toIntExact(n)));
    }

    @Test
    void aPortInUseIsAClearError() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            IOException e = assertThrows(IOException.class, () -> FoxgloveServer.start(
                    new InetSocketAddress(InetAddress.getLoopbackAddress(), taken.getLocalPort())));
            assertTrue(e.getMessage().startsWith("cannot serve Foxglove on 127.0.0.1:" + taken.getLocalPort() + ": "),
                    e.getMessage());
        }
    }

    /**
     * A viewer that stops reading: publish keeps returning, that viewer's frames are dropped and counted
     * once its queue is full, another viewer still gets every message, and the stuck one is told how
     * many it missed once it reads again.
     */
    @Test
    void aStuckViewerNeitherBlocksPublishNorStarvesOthers() throws Exception {
        int max = 8;
        FoxgloveServer s = server(max);
        s.advertise(SCAN);
        TestViewer fast = viewer(s);
        TestViewer stuck = viewer(s);
        open.add(stuck::resume); // whatever happens, before it is closed
        for (TestViewer v : List.of(fast, stuck)) {
            v.nextText("serverInfo");
            int id = v.nextText("advertise").getAsJsonArray("channels").get(0).getAsJsonObject().get("id").getAsInt();
            v.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":3,\"channelId\":" + id + "}]}");
        }
        byte[] big = new byte[256 * 1024];
        java.util.Arrays.fill(big, (byte) 'x');
        int n = awaitSubscribed(s, SCAN, fast, stuck);
        stuck.stall();
        // one message at a time, each waited for by the fast viewer, until the stuck one's queue overflows
        int firstBig = n;
        while (s.counters().framesDropped() == 0) {
            assertTrue(n - firstBig < 10_000, "nothing dropped after 10 000 messages of 256 kB to a stuck viewer");
            s.publish(SCAN, T0 + n, T0 + n, big);
            TestViewer.Frame f;
            do {
                f = fast.nextFrame();
            } while (f.logTimeNanos() != T0 + n);
            n++;
        }
        long dropped = s.counters().framesDropped();
        System.out.printf("stuck viewer: %d messages of 256 kB published before the first drop (queue %d frames)%n",
                n - firstBig, max);
        // and it goes on (the kernel's socket buffers may still take some): still no waiting, still every
        // message for the fast viewer
        while (s.counters().framesDropped() < dropped + 20) {
            assertTrue(n - firstBig < 10_000, "fewer than 20 more drops after 10 000 messages to a stuck viewer");
            s.publish(SCAN, T0 + n, T0 + n, big);
            TestViewer.Frame f;
            do {
                f = fast.nextFrame();
            } while (f.logTimeNanos() != T0 + n);
            n++;
        }
        assertEquals(n, s.counters().published());
        stuck.resume();
        // once it reads again (its backlog first: publish until the message just published reaches it,
        // its queue is then empty), a status tells it how many it missed, sent right after the first
        // message frame that fitted: so it has come before the frame of the next message
        int resumedAt = n;
        long wanted;
        TestViewer.Frame f;
        do {
            assertTrue(n - resumedAt < 10_000, "the resumed viewer got none of 10 000 new messages");
            wanted = T0 + n;
            s.publish(SCAN, wanted, wanted, json("{\"n\":" + n++ + "}"));
            f = null;
            for (TestViewer.Frame g; (g = stuck.frames.poll(10, TimeUnit.MILLISECONDS)) != null;) {
                f = g; // everything that has come, waiting for each next frame
            }
        } while (f == null || f.logTimeNanos() != wanted);
        s.publish(SCAN, T0 + n, T0 + n, json("{\"n\":" + n + "}"));
        assertEquals(T0 + n, stuck.nextFrame().logTimeNanos());
        JsonObject st = null;
        for (JsonObject o : stuck.texts) {
            if (o.get("op").getAsString().equals("status")) {
                st = o;
            }
        }
        assertTrue(st != null, "no status about the drops: " + stuck.texts);
        assertEquals(1, st.get("level").getAsInt());
        assertEquals(ClientSession.DROPPED_STATUS_ID, st.get("id").getAsString());
        assertTrue(st.get("message").getAsString().matches("\\d+ messages were not sent to this viewer.*"),
                st.toString());
    }
}
