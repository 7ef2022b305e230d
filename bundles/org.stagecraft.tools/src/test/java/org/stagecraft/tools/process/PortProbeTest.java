package org.stagecraft.tools.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The readiness probe behaves like a client Player is glad to see: banner read, orderly close. */
@Timeout(30)
class PortProbeTest {
    private static final byte[] BANNER = String.format("%-32s", "Player v.3.1.1").getBytes(StandardCharsets.US_ASCII);

    /** Accepts one connection, sends the banner, and tells how the client ended it. */
    private static CompletableFuture<String> oneConnection(ServerSocket server, byte[] greeting) {
        return CompletableFuture.supplyAsync(() -> {
            try (Socket c = server.accept()) {
                c.getOutputStream().write(greeting);
                c.getOutputStream().flush();
                InputStream in = c.getInputStream();
                return in.read() < 0 ? "eof" : "data";
            } catch (SocketException e) {
                return "reset: " + e.getMessage();
            } catch (IOException e) {
                return "error: " + e;
            }
        }, r -> Thread.ofVirtual().start(r));
    }

    @Test
    void readsTheBannerAndClosesInOrder() throws Exception {
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CompletableFuture<String> seen = oneConnection(server, BANNER);
            assertTrue(new PortProbe(1000, 2000).isOpen("127.0.0.1", server.getLocalPort(), PortProbe.PLAYER_BANNER_BYTES));
            assertEquals("eof", seen.get(10, TimeUnit.SECONDS), "the server saw an orderly close, not a reset");
        }
    }

    @Test
    void anUnfinishedBannerIsNotReady() throws Exception {
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CompletableFuture<String> seen = oneConnection(server, new byte[10]);
            assertFalse(new PortProbe(1000, 300).isOpen("127.0.0.1", server.getLocalPort(), PortProbe.PLAYER_BANNER_BYTES),
                    "10 of 32 bytes is no banner");
            assertEquals("eof", seen.get(10, TimeUnit.SECONDS));
        }
    }

    @Test
    void withoutABannerAnAcceptedConnectionIsEnoughAndClosedInOrder() throws Exception {
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CompletableFuture<String> seen = oneConnection(server, new byte[0]);
            assertTrue(new PortProbe(1000, 300).isOpen("127.0.0.1", server.getLocalPort(), 0));
            assertEquals("eof", seen.get(10, TimeUnit.SECONDS));
        }
    }

    @Test
    void aClosedPortIsNotOpen() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        assertFalse(new PortProbe(300, 300).isOpen("127.0.0.1", port, PortProbe.PLAYER_BANNER_BYTES));
    }
}
