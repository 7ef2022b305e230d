package org.stagecraft.spy.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.spy.proxy.WireObserver;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamPattern;

/**
 * The Network Spy, in one of three depths: the relay alone; plus framing, decoding and publishing to
 * a bus with two consumers (a latest-value one as a view would subscribe, a lossless one as a tool
 * would); plus the MCAP log on disk, which is exactly what {@code stagecraft spy --log} runs.
 */
public final class SpyServer {
    enum Depth {
        RELAY("spy relay only"), BUS("spy decode+bus"), LOG("spy decode+bus+log"),
        /** As every Robot Session runs it: the full spy with holds and robot data breakpoints enabled, nothing held or armed. */
        SESSION("spy as a Robot Session (+holds, breakpoint gate)");

        final String label;

        Depth(String label) {
            this.label = label;
        }
    }

    private final Path logDir;
    private final Depth depth;
    private StreamBus bus;
    private ObservationPipeline pipeline;
    private NetworkSpy spy;
    private Path log;
    private final LongAdder viewed = new LongAdder();
    private final LongAdder consumed = new LongAdder();
    private final List<String> reports = new ArrayList<>();

    SpyServer(Path logDir, Depth depth) {
        this.logDir = logDir;
        this.depth = depth;
    }

    /**
     * Runs the spy in a process of its own, as {@code stagecraft spy} would run: {@code DEPTH LOGDIR
     * UPSTREAMPORT...}. Prints "ready" and the bound ports, serves until stdin closes, then prints
     * what it observed.
     */
    public static void main(String[] args) throws IOException {
        SpyServer server = new SpyServer(Path.of(args[1]), Depth.valueOf(args[0]));
        List<InetSocketAddress> ups = new ArrayList<>();
        for (int i = 2; i < args.length; i++) {
            ups.add(new InetSocketAddress(java.net.InetAddress.getLoopbackAddress(), Integer.parseInt(args[i])));
        }
        List<InetSocketAddress> fronts = server.start(ups);
        StringBuilder line = new StringBuilder("ready");
        for (InetSocketAddress a : fronts) {
            line.append(' ').append(a.getPort());
        }
        System.out.println(line);
        System.out.flush();
        System.in.readAllBytes(); // the benchmark closes our stdin to stop us
        server.close();
        System.out.println(server.report());
    }

    List<InetSocketAddress> start(List<InetSocketAddress> upstreams) throws IOException {
        List<Route> routes = new ArrayList<>();
        for (InetSocketAddress up : upstreams) {
            routes.add(Route.loopback(0, up.getHostString(), up.getPort()));
        }
        if (depth == Depth.RELAY) {
            spy = new NetworkSpy(routes, WireObserver.NONE);
            spy.start();
            return spy.boundAddresses();
        }
        bus = new StreamBus();
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> viewed.increment());
        bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 16), m -> consumed.increment());
        LogRecorder recorder = null;
        if (depth == Depth.LOG || depth == Depth.SESSION) {
            log = Files.createTempFile(logDir, "bench-", ".mcap");
            recorder = new LogRecorder(SpyLogWriter.create(log, Map.of("tool", "relay benchmark")));
        }
        pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()), recorder, ObservationPipeline.DEFAULT_MAX_QUEUED_BYTES);
        spy = new NetworkSpy(routes, pipeline);
        if (depth == Depth.SESSION) { // before start(), as RobotSession does: connections accepted from then on are holdable
            spy.holds().setEnabled(true);
            spy.dataBreakpoints().setEnabled(true);
        }
        spy.start();
        return spy.boundAddresses();
    }

    String report() {
        return reports.isEmpty() ? "" : reports.get(reports.size() - 1);
    }

    void close() throws IOException {
        spy.close();
        if (pipeline == null) {
            return;
        }
        try {
            pipeline.close();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        bus.close();
        reports.add(String.format("%d messages decoded, %d decode problems, %d bytes not observed,"
                + " forwarding waited %.2f s in all for observation (%d stalls)%s%s",
                pipeline.messages(), pipeline.decodeProblems(), pipeline.droppedBytes(),
                pipeline.waitedForObservation().toNanos() / 1e9, pipeline.stalls(),
                log == null ? "" : String.format(", log %.1f MB", Files.size(log) / 1e6),
                pipeline.recorderError() == null ? "" : "; " + pipeline.recorderError()));
        pipeline = null;
        if (log != null) {
            Files.deleteIfExists(log);
            log = null;
        }
    }
}
