package org.stagecraft.foxglove.live;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.java_websocket.client.WebSocketClient;
import org.java_websocket.drafts.Draft_6455;
import org.java_websocket.handshake.ServerHandshake;
import org.java_websocket.protocols.IProtocol;
import org.java_websocket.protocols.Protocol;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * A viewer for the tests: Java-WebSocket's client asking for {@code foxglove.websocket.v1}, keeping what
 * it receives in queues. {@link #stall()} blocks its reading thread (as a frozen viewer would), so
 * the server's frames pile up in TCP buffers and then in the server's queue.
 */
final class TestViewer extends WebSocketClient {
    /** A message data frame, decoded. */
    record Frame(int subscriptionId, long logTimeNanos, byte[] payload) {
    }

    final BlockingQueue<JsonObject> texts = new LinkedBlockingQueue<>();
    final BlockingQueue<Frame> frames = new LinkedBlockingQueue<>();
    final BlockingQueue<Long> times = new LinkedBlockingQueue<>();
    private final CountDownLatch unstall = new CountDownLatch(1);
    private volatile boolean stalled;
    volatile String selectedProtocol;

    TestViewer(URI uri, List<IProtocol> protocols) {
        super(uri, new Draft_6455(List.of(), protocols));
    }

    static TestViewer foxglove(URI uri) {
        return new TestViewer(uri, List.of(new Protocol(LiveProtocol.SUBPROTOCOL)));
    }

    static TestViewer connected(FoxgloveServer server) throws InterruptedException {
        TestViewer v = foxglove(server.uri());
        if (!v.connectBlocking(10, TimeUnit.SECONDS)) {
            throw new AssertionError("could not connect to " + server.uri());
        }
        return v;
    }

    void stall() {
        stalled = true;
    }

    void resume() {
        unstall.countDown();
    }

    JsonObject nextText() throws InterruptedException {
        JsonObject o = texts.poll(10, TimeUnit.SECONDS);
        assertNotNull(o, "no text message within 10 s");
        return o;
    }

    JsonObject nextText(String op) throws InterruptedException {
        JsonObject o = nextText();
        assertEquals(op, o.get("op").getAsString(), "op of " + o);
        return o;
    }

    Frame nextFrame() throws InterruptedException {
        Frame f = frames.poll(10, TimeUnit.SECONDS);
        assertNotNull(f, "no message frame within 10 s");
        return f;
    }

    @Override
    public void onOpen(ServerHandshake handshake) {
        selectedProtocol = handshake.getFieldValue("Sec-WebSocket-Protocol");
    }

    @Override
    public void onMessage(String message) {
        texts.add(JsonParser.parseString(message).getAsJsonObject());
    }

    @Override
    public void onMessage(ByteBuffer bytes) {
        if (stalled) {
            try {
                unstall.await(60, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        ByteBuffer b = bytes.order(ByteOrder.LITTLE_ENDIAN);
        byte op = b.get();
        if (op == LiveProtocol.MESSAGE_DATA) {
            int sub = b.getInt();
            long t = b.getLong();
            byte[] payload = new byte[b.remaining()];
            b.get(payload);
            frames.add(new Frame(sub, t, payload));
        } else if (op == LiveProtocol.TIME) {
            times.add(b.getLong());
        } else {
            throw new AssertionError("unknown binary opcode " + op);
        }
    }

    @Override
    public void onClose(int code, String reason, boolean remote) {
    }

    @Override
    public void onError(Exception ex) {
    }
}
