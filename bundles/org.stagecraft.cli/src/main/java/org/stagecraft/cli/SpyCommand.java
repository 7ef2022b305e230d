package org.stagecraft.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.streams.StreamBus;

/**
 * {@code stagecraft spy --listen PORT --to HOST:PORT [...] [--bind ADDR] [--log FILE]}: the Network
 * Spy without the IDE, e.g. on the robot's own computer. Prints a one-line summary every second and
 * stops cleanly on Ctrl-C, closing the log.
 */
final class SpyCommand {
    static final String USAGE = "usage: stagecraft spy --listen [HOST:]PORT --to HOST:PORT [--listen ... --to ...]"
            + " [--bind ADDR] [--log FILE]";
    private static final long OBSERVER_QUEUE_BYTES = 64L << 20;

    record Options(List<Route> routes, Path log) {
    }

    int run(String[] args, PrintStream out, PrintStream err) {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            err.println("stagecraft spy: " + e.getMessage());
            err.println(USAGE);
            return 2;
        }
        // Ctrl-C runs the shutdown hooks: ours asks serve() to stop and waits until the log is closed.
        CountDownLatch stop = new CountDownLatch(1);
        CountDownLatch cleanedUp = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            stop.countDown();
            try {
                cleanedUp.await(30, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "stagecraft-spy-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            return serve(o, err, stop, System.console() != null);
        } finally {
            cleanedUp.countDown();
        }
    }

    /**
     * Runs the spy until {@code stop} opens, printing the summary line every second (overwriting it
     * on a terminal), then closes the spy, drains the pipeline and closes the log.
     */
    int serve(Options o, PrintStream err, CountDownLatch stop, boolean tty) {
        StreamBus bus = new StreamBus();
        LogRecorder recorder = null;
        if (o.log() != null) {
            try {
                Map<String, String> meta = new LinkedHashMap<>();
                meta.put("tool", "stagecraft spy");
                meta.put("routes", o.routes().toString());
                recorder = new LogRecorder(SpyLogWriter.create(o.log(), meta));
            } catch (IOException e) {
                err.println("stagecraft spy: cannot write the log " + o.log() + ": " + e.getMessage());
                bus.close();
                return 1;
            }
        }
        ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()), recorder,
                OBSERVER_QUEUE_BYTES);
        NetworkSpy spy = new NetworkSpy(o.routes(), pipeline);
        try {
            spy.start();
        } catch (IOException e) {
            err.println("stagecraft spy: " + e.getMessage());
            stop(spy, pipeline, bus);
            return 1;
        }
        for (int i = 0; i < o.routes().size(); i++) {
            InetSocketAddress a = spy.boundAddresses().get(i);
            err.println("spying " + a.getAddress().getHostAddress() + ":" + a.getPort() + " -> "
                    + o.routes().get(i).upstream().getHostString() + ":" + o.routes().get(i).upstream().getPort());
        }
        if (o.log() != null) {
            err.println("logging to " + o.log());
        }
        Summary summary = new Summary(spy, pipeline);
        try {
            while (!stop.await(1, TimeUnit.SECONDS)) {
                String line = summary.next();
                if (tty) {
                    err.print("\r" + line + "   ");
                } else {
                    err.println(line);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        stop(spy, pipeline, bus);
        err.println((tty ? "\n" : "") + "stopped: " + summary.totals());
        return 0;
    }

    private static void stop(NetworkSpy spy, ObservationPipeline pipeline, StreamBus bus) {
        spy.close();
        try {
            pipeline.close();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        bus.close();
    }

    static Options parse(String[] args) {
        List<Route> routes = new ArrayList<>();
        String bind = Route.DEFAULT_BIND;
        Path log = null;
        List<String> listens = new ArrayList<>();
        List<String> tos = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (i + 1 >= args.length) {
                throw new IllegalArgumentException(a + " needs a value");
            }
            String v = args[++i];
            switch (a) {
                case "--listen" -> listens.add(v);
                case "--to" -> tos.add(v);
                case "--bind" -> bind = v;
                case "--log" -> log = Path.of(v);
                default -> throw new IllegalArgumentException("unknown option " + a);
            }
        }
        if (listens.isEmpty() || listens.size() != tos.size()) {
            throw new IllegalArgumentException("give one --to HOST:PORT for each --listen PORT (" + listens.size()
                    + " --listen, " + tos.size() + " --to)");
        }
        for (int i = 0; i < listens.size(); i++) {
            InetSocketAddress listen = Route.address(listens.get(i), bind);
            InetSocketAddress to = Route.address(tos.get(i), "127.0.0.1");
            routes.add(new Route(listen, to));
        }
        return new Options(routes, log);
    }

    /** The live one-line summary: rates since the previous line, totals since the start. */
    private static final class Summary {
        private final NetworkSpy spy;
        private final ObservationPipeline pipeline;
        private long lastMessages;
        private long lastBytes;
        private long lastNanos = System.nanoTime();

        Summary(NetworkSpy spy, ObservationPipeline pipeline) {
            this.spy = spy;
            this.pipeline = pipeline;
        }

        String next() {
            long now = System.nanoTime();
            double secs = Math.max(1e-3, (now - lastNanos) / 1e9);
            long messages = pipeline.messages();
            long bytes = spy.bytesForwarded(Direction.CLIENT_TO_SERVER) + spy.bytesForwarded(Direction.SERVER_TO_CLIENT);
            String line = String.format("connections %d open/%d | %.0f msg/s | %.1f kB/s | decode errors %d | dropped %d B%s",
                    spy.openConnections(), spy.totalConnections(), (messages - lastMessages) / secs,
                    (bytes - lastBytes) / secs / 1000, pipeline.decodeProblems() + pipeline.unframedBytes(),
                    pipeline.droppedBytes(), pipeline.recorderError() != null ? " | " + pipeline.recorderError() : "");
            lastMessages = messages;
            lastBytes = bytes;
            lastNanos = now;
            return line;
        }

        String totals() {
            return String.format("%d connections, %d messages, %d bytes forwarded, %d decode errors, %d bytes unobserved%s",
                    spy.totalConnections(), pipeline.messages(),
                    spy.bytesForwarded(Direction.CLIENT_TO_SERVER) + spy.bytesForwarded(Direction.SERVER_TO_CLIENT),
                    pipeline.decodeProblems(), pipeline.droppedBytes(),
                    pipeline.recorderError() != null ? "; " + pipeline.recorderError() : "");
        }
    }
}
