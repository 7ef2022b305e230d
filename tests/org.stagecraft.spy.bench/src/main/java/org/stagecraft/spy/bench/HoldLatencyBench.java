package org.stagecraft.spy.bench;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.streams.StreamBus;

/**
 * Hold latency: from {@code hold()} to the zero-velocity command's last byte arriving at Player's
 * socket, through the full spy (holds enabled, decode, bus, MCAP log). Two cases: the robot program
 * idle between messages (the zero goes out on the calling thread), and the program streaming its
 * recorded CMD_VELs and data requests flat out (the zero waits for the message in flight).
 *
 * <pre>java -cp spy-bench.jar org.stagecraft.spy.bench.HoldLatencyBench [trials=2000]</pre>
 */
public final class HoldLatencyBench {
    private HoldLatencyBench() {
    }

    public static void main(String[] args) throws Exception {
        int trials = args.length > 0 ? Integer.parseInt(args[0]) : 2000;
        byte[] program = program();
        List<byte[]> messages = frame(program);
        byte[] cmdVel = messages.stream().filter(m -> isCmdVel(m) && !isZero(m)).findFirst().orElseThrow();
        byte[] request = messages.stream().filter(m -> MessageHeader.read(m, 0).type() == 3).findFirst().orElseThrow();

        try (ServerSocket player = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            LinkedBlockingQueue<Long> zeroArrivals = new LinkedBlockingQueue<>();
            Thread.ofPlatform().daemon().start(() -> playerSide(player, zeroArrivals));
            Path dir = Files.createTempDirectory("hold-bench");
            StreamBus bus = new StreamBus();
            ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()),
                    new LogRecorder(SpyLogWriter.create(dir.resolve("hold-bench.mcap"), Map.of())), 64 << 20);
            NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", player.getLocalPort())), pipeline);
            RobotHold holds = spy.holds();
            holds.setEnabled(true);
            spy.start();
            InetSocketAddress at = spy.boundAddresses().get(0);
            try (Socket s = new Socket(at.getAddress(), at.getPort())) {
                s.setTcpNoDelay(true);
                OutputStream out = s.getOutputStream();
                out.write(cmdVel); // the device is now known to the spy
                out.write(request);
                out.flush();
                for (int i = 0; i < 200; i++) { // warm-up
                    measure(holds, zeroArrivals);
                }
                long[] idle = new long[trials];
                for (int i = 0; i < trials; i++) {
                    idle[i] = measure(holds, zeroArrivals);
                }
                report("program idle between messages", idle);

                // the program streams commands and requests as fast as the socket takes them
                byte[] burst = new byte[(cmdVel.length + request.length) * 64];
                for (int i = 0; i < 64; i++) {
                    System.arraycopy(cmdVel, 0, burst, i * (cmdVel.length + request.length), cmdVel.length);
                    System.arraycopy(request, 0, burst, i * (cmdVel.length + request.length) + cmdVel.length, request.length);
                }
                Thread writer = Thread.ofPlatform().daemon().start(() -> {
                    try {
                        while (!Thread.currentThread().isInterrupted()) {
                            out.write(burst);
                        }
                    } catch (IOException e) {
                        // closed at the end
                    }
                });
                for (int i = 0; i < 200; i++) {
                    measure(holds, zeroArrivals);
                }
                long[] busy = new long[trials];
                for (int i = 0; i < trials; i++) {
                    busy[i] = measure(holds, zeroArrivals);
                }
                report("program streaming commands", busy);
                writer.interrupt();
            }
            spy.close();
            pipeline.close();
            bus.close();
        }
        // what enabling holds costs the relay while nothing is held (relay only, no observation)
        for (int round = 0; round < 3; round++) {
            double off = throughput(program, false);
            double on = throughput(program, true);
            System.out.printf("relay throughput, program stream x2000: holds off %.0f MB/s, holds enabled (not held) %.0f MB/s%n",
                    off, on);
        }
    }

    /** MB/s of the recorded program stream, 2000 times over, through a relay-only spy. */
    private static double throughput(byte[] program, boolean holdsEnabled) throws Exception {
        int repeat = 2000;
        long total = (long) program.length * repeat;
        try (ServerSocket player = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            java.util.concurrent.CompletableFuture<Long> done = new java.util.concurrent.CompletableFuture<>();
            Thread.ofPlatform().daemon().start(() -> {
                try (Socket s = player.accept()) {
                    InputStream in = s.getInputStream();
                    byte[] buf = new byte[1 << 16];
                    long got = 0;
                    for (int n; got < total && (n = in.read(buf)) >= 0;) {
                        got += n;
                    }
                    done.complete(System.nanoTime());
                } catch (IOException e) {
                    done.completeExceptionally(e);
                }
            });
            NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", player.getLocalPort())),
                    org.stagecraft.spy.proxy.WireObserver.NONE);
            spy.holds().setEnabled(holdsEnabled);
            spy.start();
            InetSocketAddress at = spy.boundAddresses().get(0);
            try (Socket s = new Socket(at.getAddress(), at.getPort())) {
                s.setTcpNoDelay(true);
                OutputStream out = s.getOutputStream();
                long t0 = System.nanoTime();
                for (int i = 0; i < repeat; i++) {
                    out.write(program);
                }
                long t1 = done.get(60, TimeUnit.SECONDS);
                return total / 1e6 / ((t1 - t0) / 1e9);
            } finally {
                spy.close();
            }
        }
    }

    /** One hold: the time until Player's side saw the zero command complete. */
    private static long measure(RobotHold holds, LinkedBlockingQueue<Long> zeroArrivals) throws InterruptedException {
        zeroArrivals.clear();
        long t0 = System.nanoTime();
        holds.hold(HoldReason.SUSPENDED);
        Long t1 = zeroArrivals.poll(10, TimeUnit.SECONDS);
        holds.release(HoldReason.SUSPENDED);
        if (t1 == null) {
            throw new IllegalStateException("no zero command reached Player");
        }
        return t1 - t0;
    }

    /** Player: frames what arrives and notes when each zero-velocity CMD_VEL is complete. */
    private static void playerSide(ServerSocket server, LinkedBlockingQueue<Long> zeroArrivals) {
        try (Socket s = server.accept()) {
            s.setTcpNoDelay(true);
            InputStream in = s.getInputStream();
            byte[] buf = new byte[1 << 16];
            byte[] pending = new byte[0];
            for (int n; (n = in.read(buf)) >= 0;) {
                long now = System.nanoTime();
                byte[] all = Arrays.copyOf(pending, pending.length + n);
                System.arraycopy(buf, 0, all, pending.length, n);
                int p = 0;
                while (all.length - p >= MessageHeader.SIZE) {
                    MessageHeader h = MessageHeader.read(all, p);
                    int len = MessageHeader.SIZE + h.size();
                    if (all.length - p < len) {
                        break;
                    }
                    byte[] m = Arrays.copyOfRange(all, p, p + len);
                    if (isCmdVel(m) && isZero(m)) {
                        zeroArrivals.add(now);
                    }
                    p += len;
                }
                pending = Arrays.copyOfRange(all, p, all.length);
            }
        } catch (IOException e) {
            // the benchmark ended
        }
    }

    private static boolean isCmdVel(byte[] m) {
        MessageHeader h = MessageHeader.read(m, 0);
        return h.interf() == 4 && h.type() == 2 && h.subtype() == 1;
    }

    private static boolean isZero(byte[] m) {
        XdrReader r = new XdrReader(m, MessageHeader.SIZE, m.length - MessageHeader.SIZE);
        return r.float64() == 0 && r.float64() == 0 && r.float64() == 0;
    }

    private static void report(String what, long[] nanos) {
        long[] s = nanos.clone();
        Arrays.sort(s);
        System.out.printf("hold latency, %s: n=%d  median %.1f µs  p90 %.1f µs  p99 %.1f µs  max %.1f µs%n", what, s.length,
                s[s.length / 2] / 1e3, s[(int) (s.length * 0.90)] / 1e3, s[(int) (s.length * 0.99)] / 1e3, s[s.length - 1] / 1e3);
    }

    private static byte[] program() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (TraceReader r = new TraceReader(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl"))) {
            for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                if (rec instanceof TraceRecord.Chunk c && c.stream().conn() == 1 && c.stream().dir() == Direction.CLIENT_TO_SERVER) {
                    out.write(c.data());
                }
            }
        }
        return out.toByteArray();
    }

    private static List<byte[]> frame(byte[] s) {
        List<byte[]> out = new java.util.ArrayList<>();
        for (int p = 0; p + MessageHeader.SIZE <= s.length;) {
            int len = MessageHeader.SIZE + MessageHeader.read(s, p).size();
            out.add(Arrays.copyOfRange(s, p, p + len));
            p += len;
        }
        return out;
    }
}
