package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.player.wire.Direction;

/** The relay itself: bytes unchanged and in order, half-close, resets, refusal, binding. */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class NetworkSpyTest {
    private final List<AutoCloseable> cleanup = new ArrayList<>();
    /**
     * Peers block in socket reads; on a small machine the common pool has a single worker, so
     * every peer gets its own virtual thread instead.
     */
    private final ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor();

    private <T> CompletableFuture<T> async(java.util.function.Supplier<T> task) {
        return CompletableFuture.supplyAsync(task, peers);
    }

    private CompletableFuture<Void> run(Runnable task) {
        return CompletableFuture.runAsync(task, peers);
    }

    @AfterEach
    void close() throws Exception {
        for (AutoCloseable c : cleanup) {
            c.close();
        }
        peers.shutdownNow();
    }

    private ServerSocket upstream() throws IOException {
        ServerSocket s = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        cleanup.add(s);
        return s;
    }

    private NetworkSpy spy(ServerSocket upstream, WireObserver observer) throws IOException {
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", upstream.getLocalPort())), observer);
        cleanup.add(spy);
        spy.start();
        return spy;
    }

    private Socket connect(NetworkSpy spy) throws IOException {
        Socket s = new Socket();
        cleanup.add(s);
        s.connect(spy.boundAddresses().get(0));
        return s;
    }

    private static byte[] random(int n, long seed) {
        byte[] b = new byte[n];
        new Random(seed).nextBytes(b);
        return b;
    }

    @Test
    void forwardsBothDirectionsUnchangedAndInOrderWithHalfClose() throws Exception {
        ServerSocket up = upstream();
        byte[] toServer = random(3_000_000, 1);
        byte[] toClient = random(2_000_000, 2);
        CompletableFuture<byte[]> serverGot = async(() -> {
            try (Socket s = up.accept()) {
                CompletableFuture<Void> send = run(() -> {
                    try {
                        s.getOutputStream().write(toClient);
                        s.shutdownOutput();
                    } catch (IOException e) {
                        throw new IllegalStateException(e);
                    }
                });
                byte[] got = s.getInputStream().readAllBytes(); // ends at the client's half-close
                send.join();
                return got;
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        RecordingObserver observer = new RecordingObserver();
        NetworkSpy spy = spy(up, observer);
        Socket client = connect(spy);
        CompletableFuture<Void> send = run(() -> {
            try {
                client.getOutputStream().write(toServer);
                client.shutdownOutput();
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        byte[] clientGot = client.getInputStream().readAllBytes();
        send.join();
        assertArrayEquals(toServer, serverGot.get(30, TimeUnit.SECONDS));
        assertArrayEquals(toClient, clientGot);
        assertTrue(observer.closed.await(10, TimeUnit.SECONDS));
        assertArrayEquals(toServer, observer.bytes(Direction.CLIENT_TO_SERVER), "observer sees what was forwarded");
        assertArrayEquals(toClient, observer.bytes(Direction.SERVER_TO_CLIENT));
        assertEquals(toServer.length, spy.bytesForwarded(Direction.CLIENT_TO_SERVER));
        assertEquals("closed", observer.reason);
        assertEquals(0, spy.openConnections());
    }

    @Test
    void halfCloseByTheClientStillLetsTheServerAnswer() throws Exception {
        ServerSocket up = upstream();
        CompletableFuture<Void> server = run(() -> {
            try (Socket s = up.accept()) {
                byte[] req = s.getInputStream().readAllBytes(); // waits for the client's FIN
                s.getOutputStream().write(("echo:" + new String(req)).getBytes());
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        Socket client = connect(spy(up, WireObserver.NONE));
        client.getOutputStream().write("ping".getBytes());
        client.shutdownOutput();
        assertEquals("echo:ping", new String(client.getInputStream().readAllBytes()));
        server.get(10, TimeUnit.SECONDS);
    }

    @Test
    void anUpstreamResetResetsTheClient() throws Exception {
        ServerSocket up = upstream();
        run(() -> {
            try {
                Socket s = up.accept();
                s.getInputStream().read();
                s.setSoLinger(true, 0);
                s.close(); // RST
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        RecordingObserver observer = new RecordingObserver();
        Socket client = connect(spy(up, observer));
        client.getOutputStream().write(1);
        InputStream in = client.getInputStream();
        assertThrows(SocketException.class, () -> {
            while (in.read() >= 0) {
                // a reset must surface as an exception, not as an orderly end
            }
        });
        assertTrue(observer.closed.await(10, TimeUnit.SECONDS));
        assertTrue(observer.reason.startsWith("upstream side failed"), observer.reason);
    }

    @Test
    void aClientResetResetsTheUpstream() throws Exception {
        ServerSocket up = upstream();
        CountDownLatch firstByte = new CountDownLatch(1);
        CompletableFuture<Throwable> upstreamSaw = async(() -> {
            try (Socket s = up.accept()) {
                InputStream in = s.getInputStream();
                in.read();
                firstByte.countDown();
                while (in.read() >= 0) {
                    // an orderly end here would be wrong: the client reset
                }
                return null;
            } catch (IOException e) {
                return e;
            }
        });
        RecordingObserver observer = new RecordingObserver();
        Socket client = connect(spy(up, observer));
        client.getOutputStream().write(1);
        assertTrue(firstByte.await(10, TimeUnit.SECONDS));
        client.setSoLinger(true, 0);
        client.close(); // RST
        Throwable seen = upstreamSaw.get(20, TimeUnit.SECONDS);
        assertTrue(seen instanceof SocketException, "Player must see a reset, saw " + seen);
        assertTrue(observer.closed.await(10, TimeUnit.SECONDS));
        assertTrue(observer.reason.startsWith("client side failed"), observer.reason);
    }

    @Test
    void aRefusingUpstreamResetsTheClient() throws Exception {
        ServerSocket up = upstream();
        int deadPort = up.getLocalPort();
        up.close(); // nothing listens there now
        RecordingObserver observer = new RecordingObserver();
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", deadPort)), observer)
                .upstreamGrace(Duration.ZERO);
        List<SpyNotice> notices = new CopyOnWriteArrayList<>();
        spy.addListener(notices::add);
        cleanup.add(spy);
        spy.start();
        Socket client = connect(spy);
        assertThrows(SocketException.class, () -> client.getInputStream().read());
        assertTrue(observer.closed.await(10, TimeUnit.SECONDS));
        assertTrue(observer.reason.contains("refused"), observer.reason);
        assertTrue(observer.reason.contains(":" + deadPort), observer.reason);
        assertEquals(List.of(SpyNotice.Kind.UPSTREAM_REFUSED), notices.stream().map(SpyNotice::kind).toList(),
                "no grace: one attempt, one refusal said");
    }

    /** A robot program started with Player often connects first: it must wait for Player, not be reset. */
    @Test
    void aClientThatComesBeforePlayerIsRelayedByteExactOnceItListens() throws Exception {
        int playerPort;
        try (ServerSocket probe = upstream()) {
            playerPort = probe.getLocalPort(); // free again once closed: Player will listen there later
        }
        RecordingObserver observer = new RecordingObserver();
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", playerPort)), observer)
                .upstreamGrace(Duration.ofSeconds(30));
        List<SpyNotice> notices = new CopyOnWriteArrayList<>();
        CountDownLatch waiting = new CountDownLatch(1);
        spy.addListener(n -> {
            notices.add(n);
            if (n.kind() == SpyNotice.Kind.UPSTREAM_WAITING) {
                waiting.countDown();
            }
        });
        cleanup.add(spy);
        spy.start();
        byte[] request = random(200_000, 11);
        byte[] reply = random(300_000, 12);
        Socket client = connect(spy);
        CompletableFuture<Void> sent = run(() -> {
            try {
                client.getOutputStream().write(request); // sent before Player listens: must wait, not vanish
                client.shutdownOutput();
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        assertTrue(waiting.await(20, TimeUnit.SECONDS), "the spy says it waits for Player");

        ServerSocket player = new ServerSocket();
        cleanup.add(player);
        player.setReuseAddress(true);
        player.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), playerPort));
        CompletableFuture<byte[]> playerGot = async(() -> {
            try (Socket s = player.accept()) {
                s.getOutputStream().write(reply);
                s.shutdownOutput();
                return s.getInputStream().readAllBytes();
            } catch (IOException e) {
                throw new RuntimeException(e);
            }
        });
        byte[] clientGot = client.getInputStream().readAllBytes();
        sent.get(20, TimeUnit.SECONDS);
        assertArrayEquals(request, playerGot.get(20, TimeUnit.SECONDS));
        assertArrayEquals(reply, clientGot);
        assertTrue(observer.closed.await(10, TimeUnit.SECONDS));
        assertEquals("closed", observer.reason);
        assertEquals(List.of(SpyNotice.Kind.UPSTREAM_WAITING, SpyNotice.Kind.UPSTREAM_REACHED),
                notices.stream().map(SpyNotice::kind).toList());
        assertTrue(notices.get(0).text().contains("127.0.0.1:" + playerPort), notices.get(0).text());
    }

    @Test
    void aRefusalAfterTheGracePeriodIsSaidToListenersAndTheObserver() throws Exception {
        ServerSocket up = upstream();
        int deadPort = up.getLocalPort();
        up.close();
        RecordingObserver observer = new RecordingObserver();
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", deadPort)), observer)
                .upstreamGrace(Duration.ofMillis(400));
        List<SpyNotice> notices = new CopyOnWriteArrayList<>();
        spy.addListener(notices::add);
        cleanup.add(spy);
        spy.start();
        long t0 = System.nanoTime();
        Socket client = connect(spy);
        assertThrows(SocketException.class, () -> client.getInputStream().read());
        assertTrue(System.nanoTime() - t0 >= 300_000_000L, "the spy kept trying for the grace period");
        assertTrue(observer.closed.await(10, TimeUnit.SECONDS));
        assertEquals(List.of(SpyNotice.Kind.UPSTREAM_WAITING, SpyNotice.Kind.UPSTREAM_REFUSED),
                notices.stream().map(SpyNotice::kind).toList());
        SpyNotice refused = notices.get(1);
        assertTrue(refused.kind().isFailure());
        assertTrue(refused.text().contains("Player at 127.0.0.1:" + deadPort + " refused connection 1"), refused.text());
        assertTrue(refused.text().contains("0.4 s"), refused.text());
        assertEquals(notices, observer.notices, "the observer (log and bus) hears the same notices");
    }

    @Test
    void anAddressOfAnotherMachineIsNamedAsSuch() {
        // 192.0.2.1 is TEST-NET-1 (RFC 5737): never an address of this machine
        NetworkSpy spy = new NetworkSpy(List.of(Route.of("192.0.2.1", 0, "127.0.0.1", 7665)), WireObserver.NONE);
        cleanup.add(spy);
        IOException e = assertThrows(IOException.class, spy::start);
        assertTrue(e.getMessage().contains("192.0.2.1 is not an address of this machine"), e.getMessage());
    }

    @Test
    void bindFailuresAreToldApartByTheirCause() {
        InetSocketAddress low = new InetSocketAddress(InetAddress.getLoopbackAddress(), 80);
        assertEquals("permission denied: ports below 1024 need administrator rights",
                BindFailure.explain(low, new java.net.BindException("Permission denied")));
        assertEquals("port 80 is already in use on 127.0.0.1",
                BindFailure.explain(low, new java.net.BindException("Address already in use")));
        assertTrue(BindFailure.explain(low, new java.net.BindException("Cannot assign requested address"))
                .contains("not an address of this machine"));
    }

    @Test
    void bindsLoopbackByDefaultAndNamesAPortInUse() throws Exception {
        ServerSocket up = upstream();
        NetworkSpy spy = spy(up, WireObserver.NONE);
        InetSocketAddress bound = spy.boundAddresses().get(0);
        assertTrue(bound.getAddress().isLoopbackAddress(), bound.toString());

        NetworkSpy clash = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", 7000),
                Route.loopback(bound.getPort(), "127.0.0.1", 7001)), WireObserver.NONE);
        IOException e = assertThrows(IOException.class, clash::start);
        assertTrue(e.getMessage().contains("127.0.0.1:" + bound.getPort()), e.getMessage());
        assertTrue(e.getMessage().contains("already in use"), e.getMessage());
        assertTrue(clash.boundAddresses().isEmpty(), "nothing stays bound after a failed start");
    }

    @Test
    void anObserverThatThrowsCannotStopTheBytes() throws Exception {
        ServerSocket up = upstream();
        CompletableFuture<byte[]> server = async(() -> {
            try (Socket s = up.accept()) {
                return s.getInputStream().readAllBytes();
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        WireObserver broken = new WireObserver() {
            @Override
            public void opened(ConnectionInfo c, long t) {
                throw new IllegalStateException("bug");
            }

            @Override
            public void chunk(ConnectionInfo c, Direction d, byte[] data, long t) {
                throw new IllegalStateException("bug");
            }

            @Override
            public void closed(ConnectionInfo c, long t, String r) {
            }
        };
        NetworkSpy spy = spy(up, broken);
        Socket client = connect(spy);
        byte[] data = random(500_000, 3);
        client.getOutputStream().write(data);
        client.shutdownOutput();
        assertArrayEquals(data, server.get(20, TimeUnit.SECONDS));
        assertTrue(spy.observerFailures() >= 2);
    }

    @Test
    void manyRoutesAndClientsAtOnce() throws Exception {
        int routes = 6;
        List<Route> list = new ArrayList<>();
        List<ServerSocket> ups = new ArrayList<>();
        for (int i = 0; i < routes; i++) {
            ServerSocket up = upstream();
            ups.add(up);
            list.add(Route.loopback(0, "127.0.0.1", up.getLocalPort()));
            Thread.ofVirtual().start(() -> {
                while (!up.isClosed()) {
                    try {
                        Socket s = up.accept();
                        Thread.ofVirtual().start(() -> {
                            try (s) {
                                s.getInputStream().transferTo(s.getOutputStream()); // echo
                            } catch (IOException ignored) {
                                // test peer
                            }
                        });
                    } catch (IOException e) {
                        return;
                    }
                }
            });
        }
        NetworkSpy spy = new NetworkSpy(list, WireObserver.NONE);
        cleanup.add(spy);
        spy.start();
        List<CompletableFuture<Boolean>> clients = new ArrayList<>();
        for (int i = 0; i < routes * 5; i++) {
            InetSocketAddress at = spy.boundAddresses().get(i % routes);
            byte[] data = random(100_000, i);
            clients.add(async(() -> {
                try (Socket s = new Socket()) {
                    s.connect(at);
                    CompletableFuture<Void> w = run(() -> {
                        try {
                            s.getOutputStream().write(data);
                            s.shutdownOutput();
                        } catch (IOException e) {
                            throw new IllegalStateException(e);
                        }
                    });
                    byte[] back = s.getInputStream().readAllBytes();
                    w.join();
                    return java.util.Arrays.equals(data, back);
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }));
        }
        for (CompletableFuture<Boolean> c : clients) {
            assertTrue(c.get(30, TimeUnit.SECONDS));
        }
        assertEquals(routes * 5L, spy.totalConnections());
    }

    /** Keeps what it is told, for assertions. */
    static final class RecordingObserver implements WireObserver {
        final java.io.ByteArrayOutputStream c2s = new java.io.ByteArrayOutputStream();
        final java.io.ByteArrayOutputStream s2c = new java.io.ByteArrayOutputStream();
        final CountDownLatch closed = new CountDownLatch(1);
        volatile String reason;
        final List<SpyNotice> notices = new CopyOnWriteArrayList<>();

        @Override
        public void notice(SpyNotice notice, long timeNanos) {
            notices.add(notice);
        }

        @Override
        public void opened(ConnectionInfo connection, long timeNanos) {
        }

        @Override
        public synchronized void chunk(ConnectionInfo connection, Direction dir, byte[] data, long timeNanos) {
            (dir == Direction.CLIENT_TO_SERVER ? c2s : s2c).writeBytes(data);
        }

        @Override
        public void closed(ConnectionInfo connection, long timeNanos, String reason) {
            this.reason = reason;
            closed.countDown();
        }

        synchronized byte[] bytes(Direction dir) {
            return (dir == Direction.CLIENT_TO_SERVER ? c2s : s2c).toByteArray();
        }
    }
}
