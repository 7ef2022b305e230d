package org.stagecraft.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.java_websocket.client.WebSocketClient;
import org.java_websocket.drafts.Draft_6455;
import org.java_websocket.handshake.ServerHandshake;
import org.java_websocket.protocols.Protocol;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.streams.StreamMessage;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** {@code stagecraft spy --foxglove}: a recorded session relayed byte-exact while viewers watch it live. */
@Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SpyFoxgloveTest {
    @TempDir
    Path tmp;

    /** A Foxglove viewer that subscribes to every channel it is told of; may stop reading. */
    private static final class Viewer extends WebSocketClient {
        final BlockingQueue<JsonObject> texts = new LinkedBlockingQueue<>();
        final Map<Integer, String> topics = new ConcurrentHashMap<>();
        final Map<Integer, String> schemaNames = new ConcurrentHashMap<>();
        final Map<String, Integer> messagesPerTopic = new ConcurrentHashMap<>();
        final Map<Integer, Integer> subscriptionChannel = new ConcurrentHashMap<>();
        final CountDownLatch firstFrame = new CountDownLatch(1);
        /** Opens once a laser scan channel was advertised and the viewer's subscribe to it sent. */
        final CountDownLatch laserSubscribeSent = new CountDownLatch(1);
        final CountDownLatch resume = new CountDownLatch(1);
        final boolean stuck;
        private int nextSubscription;

        Viewer(URI uri, boolean stuck) {
            super(uri, new Draft_6455(List.of(), List.of(new Protocol("foxglove.websocket.v1"))));
            this.stuck = stuck;
        }

        @Override
        public void onOpen(ServerHandshake h) {
        }

        @Override
        public synchronized void onMessage(String message) {
            JsonObject o = JsonParser.parseString(message).getAsJsonObject();
            texts.add(o);
            if (o.get("op").getAsString().equals("advertise")) {
                StringBuilder subs = new StringBuilder();
                for (JsonElement c : o.getAsJsonArray("channels")) {
                    int id = c.getAsJsonObject().get("id").getAsInt();
                    topics.put(id, c.getAsJsonObject().get("topic").getAsString());
                    schemaNames.put(id, c.getAsJsonObject().get("schemaName").getAsString());
                    int sub = nextSubscription++;
                    subscriptionChannel.put(sub, id);
                    subs.append(subs.isEmpty() ? "" : ",").append("{\"id\":").append(sub).append(",\"channelId\":").append(id).append('}');
                }
                if (!subs.isEmpty()) {
                    send("{\"op\":\"subscribe\",\"subscriptions\":[" + subs + "]}");
                }
                if (schemaNames.containsValue("foxglove.LaserScan")) {
                    laserSubscribeSent.countDown();
                }
            }
        }

        @Override
        public void onMessage(ByteBuffer bytes) {
            firstFrame.countDown();
            if (stuck) {
                try {
                    resume.await(60, TimeUnit.SECONDS); // a frozen viewer: reads nothing more
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            ByteBuffer b = bytes.order(ByteOrder.LITTLE_ENDIAN);
            if (b.get() != 1) {
                return; // time
            }
            int sub = b.getInt();
            b.getLong();
            byte[] payload = new byte[b.remaining()];
            b.get(payload);
            JsonParser.parseString(new String(payload, StandardCharsets.UTF_8)); // JSON, or this throws
            messagesPerTopic.merge(topics.get(subscriptionChannel.get(sub)), 1, Integer::sum);
        }

        final CountDownLatch closed = new CountDownLatch(1);

        @Override
        public void onClose(int code, String reason, boolean remote) {
            closed.countDown();
        }

        /**
         * Closes with the closing handshake, but waits for it a bounded time (closeBlocking waits for
         * ever), so that a failure before it is reported instead of hidden behind a hanging clean-up.
         */
        void closeWithin(Duration d) throws InterruptedException {
            close();
            if (!closed.await(d.toMillis(), TimeUnit.MILLISECONDS)) {
                closeConnection(org.java_websocket.framing.CloseFrame.ABNORMAL_CLOSE, "no close from the server within " + d);
                assertTrue(closed.await(d.toMillis(), TimeUnit.MILLISECONDS), "the viewer's connection did not end");
            }
        }

        @Override
        public void onError(Exception ex) {
        }

        JsonObject next(String op) throws InterruptedException {
            while (true) {
                JsonObject o = texts.poll(20, TimeUnit.SECONDS);
                assertNotNull(o, "no '" + op + "' within 20 s");
                if (o.get("op").getAsString().equals(op)) {
                    return o;
                }
            }
        }
    }

    private record Run(boolean wireExact, String totals, Viewer viewer) {
    }

    /**
     * Player's side of the recording, raw: the first quarter of its bytes, then (once {@code go} opens)
     * the rest; returns what the robot program sent.
     */
    private static byte[] pausedPlayer(Socket s, byte[] server, CountDownLatch go) throws Exception {
        try (s; ExecutorService reader = Executors.newVirtualThreadPerTaskExecutor()) {
            Future<byte[]> received = reader.submit(() -> s.getInputStream().readAllBytes());
            int head = server.length / 4;
            s.getOutputStream().write(server, 0, head);
            assertTrue(go.await(60, TimeUnit.SECONDS), "the viewer did not subscribe within 60 s");
            s.getOutputStream().write(server, head, server.length - head);
            s.shutdownOutput();
            return received.get(60, TimeUnit.SECONDS);
        }
    }

    /**
     * Relays one recorded session through {@code spy --foxglove 0} with a viewer connected before the
     * robot; Player holds back three quarters of its bytes until {@code subscribed} has run.
     */
    private Run relay(SpyCommand command, boolean stuckViewer, Consumer<Viewer> subscribed, String... extra) throws Exception {
        RecordedConnection rc = RecordedConnection.read(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl")).get(0);
        PrintedLines err = new PrintedLines();
        CountDownLatch stop = new CountDownLatch(1);
        CountDownLatch go = new CountDownLatch(1);
        try (ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();
                ServerSocket player = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Future<byte[]> served = threads.submit(() -> pausedPlayer(player.accept(), rc.serverBytes(), go));
            String[] args = {"--listen", "0", "--to", "127.0.0.1:" + player.getLocalPort(), "--foxglove", "0"};
            String[] all = Arrays.copyOf(args, args.length + extra.length);
            System.arraycopy(extra, 0, all, args.length, extra.length);
            Future<Integer> spy = threads.submit(() -> command.serve(SpyCommand.parse(all),
                    new PrintStream(err, true, StandardCharsets.UTF_8), stop, false));
            int port = Integer.parseInt(err.await(Pattern.compile("spying 127\\.0\\.0\\.1:(\\d+) -> "), 20_000));
            String ws = err.await(Pattern.compile("serving Foxglove on (ws://127\\.0\\.0\\.1:\\d+)\\n"), 20_000);
            Viewer viewer = new Viewer(URI.create(ws), stuckViewer);
            try {
                assertTrue(viewer.connectBlocking(20, TimeUnit.SECONDS), "no connection to " + ws);
                viewer.next("serverInfo");
                Future<ReplayPeer.Result> program = threads.submit(
                        () -> ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), port), rc));
                subscribed.accept(viewer);
                go.countDown();
                boolean exact = program.get(60, TimeUnit.SECONDS).matches()
                        && Arrays.equals(rc.clientBytes(), served.get(60, TimeUnit.SECONDS));
                err.await(Pattern.compile("connections 0 open/(1) "), 20_000);
                if (!stuckViewer) { // the robot's connection has ended: its channels are withdrawn
                    while (!viewer.next("unadvertise").getAsJsonArray("channelIds").asList().stream()
                            .anyMatch(id -> viewer.topics.get(id.getAsInt()).startsWith("/robot"))) {
                        // a Player channel advertised anew with a grown schema: not the end yet
                    }
                }
                stop.countDown();
                assertEquals(0, spy.get(20, TimeUnit.SECONDS));
                String totals = err.await(Pattern.compile("stopped: (.*)\\n"), 20_000);
                return new Run(exact, totals, viewer);
            } finally {
                viewer.resume.countDown();
                viewer.closeWithin(Duration.ofSeconds(10));
            }
        }
    }

    /** Waits until the viewer has subscribed to a laser scan channel, and the server has made the subscription. */
    private static void laserSubscribed(Viewer v) {
        try {
            assertTrue(v.laserSubscribeSent.await(20, TimeUnit.SECONDS), "no laser channel advertised: " + v.topics);
            // a barrier: requests are answered in order, so once this one's error comes back, the
            // subscriptions the viewer sent before it are in effect
            v.send("{\"op\":\"unsubscribe\",\"subscriptionIds\":[999999]}");
            while (true) {
                JsonObject st = v.next("status");
                if (st.get("message").getAsString().contains("no subscription 999999")) {
                    return;
                }
            }
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void viewersSeeTheRobotLiveAndItsChannelsGoWhenItsConnectionEnds() throws Exception {
        Run r = relay(new SpyCommand(), false, SpyFoxgloveTest::laserSubscribed);
        assertTrue(r.wireExact(), "the bytes either end received differ from the recording");
        assertTrue(r.viewer().topics.values().stream().anyMatch(t -> t.endsWith("/tf")), r.viewer().topics.toString());
        Integer scans = r.viewer().messagesPerTopic.entrySet().stream().filter(e -> e.getKey().contains("laser"))
                .map(Map.Entry::getValue).findFirst().orElse(0);
        assertTrue(scans > 0, "no laser message reached the viewer: " + r.viewer().messagesPerTopic);
        assertTrue(r.totals().contains("foxglove 1 viewers served, 0 dropped, 0 not converted"), r.totals());
    }

    /**
     * A viewer that stops reading after its first frame, fed 256 kB per bus message: the robot's bytes
     * still pass unchanged, and what the viewer could not take is counted.
     */
    @Test
    void aStuckViewerDoesNotStallTheRelayAndItsDropsAreCounted() throws Exception {
        FoxgloveChannel big = FoxgloveChannel.json("/big", "test.Big", "{\"type\":\"string\"}");
        byte[] payload = new byte[256 * 1024];
        Arrays.fill(payload, (byte) 'x');
        payload[0] = '"';
        payload[payload.length - 1] = '"';
        Function<FoxgloveSink, Consumer<StreamMessage>> inflate = sink -> {
            sink.advertise(big);
            return m -> sink.publish(big, m.timeNanos(), m.timeNanos(), payload);
        };
        Run r = relay(new SpyCommand(inflate), true, v -> {
        }, "--foxglove-queue", "8");
        assertTrue(r.wireExact(), "the bytes either end received differ from the recording");
        Matcher m = Pattern.compile("foxglove 1 viewers served, (\\d+) dropped").matcher(r.totals());
        assertTrue(m.find(), r.totals());
        assertTrue(Long.parseLong(m.group(1)) > 0, "nothing dropped for the stuck viewer: " + r.totals());
        System.out.println("stuck viewer: " + r.totals());
    }

    @Test
    void theLiveViewListensOnLoopbackUnlessToldOtherwise() {
        assertTrue(SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--foxglove", "8765"}).foxglove()
                .getAddress().isLoopbackAddress());
        assertEquals(8765, SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--foxglove", "8765"}).foxglove().getPort());
        assertTrue(SpyCommand.parse(new String[] {"--foxglove", "8765", "--listen", "1", "--to", "2", "--bind", "0.0.0.0"})
                .foxglove().getAddress().isAnyLocalAddress());
        assertTrue(SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--foxglove", "0.0.0.0:8765"}).foxglove()
                .getAddress().isAnyLocalAddress());
        assertEquals(null, SpyCommand.parse(new String[] {"--listen", "1", "--to", "2"}).foxglove());
        assertEquals(1024, SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--foxglove", "1"}).foxgloveQueue());
        assertEquals(16, SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--foxglove", "1", "--foxglove-queue",
                "16"}).foxgloveQueue());
        IllegalArgumentException q = assertThrows(IllegalArgumentException.class, () -> SpyCommand.parse(
                new String[] {"--listen", "1", "--to", "2", "--foxglove", "1", "--foxglove-queue", "0"}));
        assertTrue(q.getMessage().contains("--foxglove-queue '0' is not a number of messages"), q.getMessage());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SpyCommand.parse(new String[] {"--listen", "1", "--to", "2", "--foxglove", "eighty"}));
        assertTrue(e.getMessage().startsWith("--foxglove: 'eighty' is not HOST:PORT or PORT"), e.getMessage());
    }

    @Test
    void aFoxglovePortInUseIsReportedAndLeavesNoLog() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 5, InetAddress.getLoopbackAddress())) {
            Path log = tmp.resolve("s.mcap");
            PrintedLines err = new PrintedLines();
            int code = new SpyCommand().serve(SpyCommand.parse(new String[] {"--listen", "0", "--to", "7665", "--log",
                    log.toString(), "--foxglove", String.valueOf(taken.getLocalPort())}),
                    new PrintStream(err, true, StandardCharsets.UTF_8), new CountDownLatch(1), false);
            assertEquals(1, code);
            assertTrue(err.text().contains("stagecraft spy: cannot serve Foxglove on 127.0.0.1:" + taken.getLocalPort() + ": "),
                    err.text());
            assertFalse(err.text().contains("\tat "), "a stack trace: " + err.text());
            assertFalse(Files.exists(log));
        }
    }
}
