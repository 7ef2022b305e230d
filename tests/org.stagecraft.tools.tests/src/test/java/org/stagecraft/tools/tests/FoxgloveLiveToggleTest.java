package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.handlers.IHandlerService;
import org.java_websocket.client.WebSocketClient;
import org.java_websocket.drafts.Draft_6455;
import org.java_websocket.handshake.ServerHandshake;
import org.java_websocket.protocols.Protocol;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyDiagnostic;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;
import org.stagecraft.tools.ui.foxglove.FoxgloveLive;
import org.stagecraft.tools.ui.foxglove.FoxgloveLiveHandler;
import org.stagecraft.tools.ui.foxglove.FoxgloveLivePreferences;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The Foxglove Live toggle in a running workbench: pressing it serves the workbench bus over the
 * Foxglove WebSocket protocol (a real client connects, is told the channels, gets a message), pressing
 * it again stops serving and closes the client. Port 0: the server picks a free one.
 */
@LogsErrors({ "'127\\.0\\.0\\.1:eighty' is not HOST:PORT" })
class FoxgloveLiveToggleTest {
    private static final Duration TIMEOUT = Duration.ofSeconds(20);

    /** A Foxglove client: Java-WebSocket's, asking for foxglove.websocket.v1. */
    private static final class Viewer extends WebSocketClient {
        final BlockingQueue<JsonObject> texts = new LinkedBlockingQueue<>();
        final BlockingQueue<byte[]> payloads = new LinkedBlockingQueue<>();
        final CountDownLatch closed = new CountDownLatch(1);

        Viewer(URI uri) {
            super(uri, new Draft_6455(List.of(), List.of(new Protocol("foxglove.websocket.v1"))));
        }

        @Override
        public void onOpen(ServerHandshake h) {
        }

        @Override
        public void onMessage(String message) {
            texts.add(JsonParser.parseString(message).getAsJsonObject());
        }

        @Override
        public void onMessage(ByteBuffer bytes) {
            ByteBuffer b = bytes.order(ByteOrder.LITTLE_ENDIAN);
            if (b.get() == 1) {
                b.getInt();
                b.getLong();
                byte[] p = new byte[b.remaining()];
                b.get(p);
                payloads.add(p);
            }
        }

        @Override
        public void onClose(int code, String reason, boolean remote) {
            closed.countDown();
        }

        @Override
        public void onError(Exception ex) {
        }

        JsonObject next(String op) throws InterruptedException {
            while (true) {
                JsonObject o = texts.poll(TIMEOUT.toSeconds(), TimeUnit.SECONDS);
                assertNotNull(o, "no '" + op + "' within " + TIMEOUT);
                if (o.get("op").getAsString().equals(op)) {
                    return o;
                }
            }
        }
    }

    private static void pressToggle() {
        AtomicReference<Exception> failed = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand(FoxgloveLiveHandler.COMMAND, null);
            } catch (Exception e) {
                failed.set(e);
            }
        });
        if (failed.get() != null) {
            throw new AssertionError("the Foxglove Live command failed", failed.get());
        }
    }

    private static void diagnostic(String text) {
        ConnectionInfo c = new ConnectionInfo(7, 6665, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");
        WorkbenchBus.get().publish(new StreamMessage(SpyStreams.diagnosticKey(c, Direction.SERVER_TO_CLIENT),
                System.currentTimeMillis() * 1_000_000L, new SpyDiagnostic(c, Direction.SERVER_TO_CLIENT, 0, text)));
    }

    @AfterEach
    void off() throws Exception {
        FoxgloveLivePreferences.set(false, FoxgloveLivePreferences.DEFAULT_ADDRESS);
        Await.until("the live view has stopped", TIMEOUT, () -> !FoxgloveLive.get().isServing());
    }

    @Test
    void theToggleServesTheWorkbenchBusToAFoxgloveClientAndStops() throws Exception {
        FoxgloveLivePreferences.set(false, "127.0.0.1:0");
        FoxgloveLive.get().followPreferences();
        assertFalse(FoxgloveLive.get().isServing());

        pressToggle();
        assertTrue(FoxgloveLivePreferences.enabled(), "the toggle turns the preference on");
        Await.until("the live view serves", TIMEOUT, () -> FoxgloveLive.get().isServing(), () -> "" + FoxgloveLive.get().problem());
        URI uri = FoxgloveLive.get().uri();
        assertTrue(uri.toString().startsWith("ws://127.0.0.1:"), uri.toString());

        Viewer v = new Viewer(uri);
        try {
            assertTrue(v.connectBlocking(TIMEOUT.toSeconds(), TimeUnit.SECONDS), "no connection to " + uri);
            assertEquals("Stagecraft", v.next("serverInfo").get("name").getAsString());
            v.next("advertise");
            // a spy diagnostic on the workbench bus becomes a foxglove.Log channel
            diagnostic("first");
            int logChannel = -1;
            while (logChannel < 0) {
                for (JsonElement c : v.next("advertise").getAsJsonArray("channels")) {
                    if (c.getAsJsonObject().get("schemaName").getAsString().equals("foxglove.Log")) {
                        logChannel = c.getAsJsonObject().get("id").getAsInt();
                    }
                }
            }
            v.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":" + logChannel + "}]}");
            // the subscription is made on the server's thread: diagnostics until one arrives. "first" may arrive
            // too: the bus's thread advertises its channel and then publishes it, and the subscription can
            // come in between; every frame must be one of these diagnostics as a foxglove.Log
            String json = null;
            for (int i = 0; i < 500 && (json == null || !json.contains("second")); i++) {
                diagnostic("second " + i);
                byte[] got = v.payloads.poll(20, TimeUnit.MILLISECONDS);
                if (got != null) {
                    json = new String(got, StandardCharsets.UTF_8);
                    assertTrue(json.contains("\"message\":\"connection") && (json.contains(": first\"")
                            || json.contains(": second ")), "a foxglove.Log of a diagnostic published here: " + json);
                }
            }
            assertNotNull(json, "no message frame for the subscribed foxglove.Log channel");
            assertTrue(json.contains("second"), json);

            pressToggle();
            assertFalse(FoxgloveLivePreferences.enabled(), "the second press turns the preference off");
            Await.until("the live view has stopped", TIMEOUT, () -> !FoxgloveLive.get().isServing());
            assertTrue(v.closed.await(TIMEOUT.toSeconds(), TimeUnit.SECONDS), "the client was not disconnected");
        } finally {
            v.closeBlocking();
        }
    }

    @Test
    void aBadAddressIsSaidNotServed() throws Exception {
        FoxgloveLive.get().followPreferences();
        FoxgloveLivePreferences.set(true, "127.0.0.1:eighty");
        Await.until("the problem is known", TIMEOUT, () -> FoxgloveLive.get().problem() != null);
        assertFalse(FoxgloveLive.get().isServing());
        assertTrue(FoxgloveLive.get().problem().contains("'127.0.0.1:eighty' is not HOST:PORT or PORT"),
                FoxgloveLive.get().problem());
    }
}
