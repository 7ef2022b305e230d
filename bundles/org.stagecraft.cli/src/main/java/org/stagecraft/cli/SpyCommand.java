package org.stagecraft.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import java.util.function.Function;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.foxglove.live.BusRelay;
import org.stagecraft.foxglove.live.EndOfConnections;
import org.stagecraft.foxglove.live.FoxgloveServer;
import org.stagecraft.foxglove.live.LiveScene;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.fields.ConditionException;
import org.stagecraft.replay.fields.StreamCondition;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.spy.proxy.SpyListener;
import org.stagecraft.spy.proxy.WireObserver;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;

/**
 * {@code stagecraft spy --listen PORT --to HOST:PORT [...] [--bind ADDR] [--log FILE] [--foxglove [ADDR:]PORT]}:
 * the Network Spy without the IDE, e.g. on the robot's own computer. Prints a one-line summary every
 * second and stops cleanly on Ctrl-C, closing the log. With {@code --foxglove}, it also serves the live
 * streams to Foxglove or Lichtblick over the Foxglove WebSocket protocol (docs/foxglove.md). With
 * {@code --break}, robot data breakpoints: when a message from Player satisfies one, the robots are held,
 * the hit is logged and printed, and Enter (or SIGUSR1) releases them (docs/debugging-robots.md).
 */
final class SpyCommand {
    static final String USAGE = "usage: stagecraft spy --listen [HOST:]PORT --to HOST:PORT [--listen ... --to ...]"
            + " [--bind ADDR] [--log FILE] [--upstream-grace SECONDS] [--observation-wait SECONDS]"
            + " [--foxglove [ADDR:]PORT [--foxglove-queue MESSAGES]] [--break 'DEVICE CONDITION' ... [--break-wait SECONDS]]";

    /** The live view's converter: the export's channels (Foxglove's schemas, and Player's own messages decoded). */
    static final Function<FoxgloveSink, Consumer<StreamMessage>> FOXGLOVE_SCENE = LiveScene.converter();

    /**
     * @param foxglove      where to serve the live view, or null for none
     * @param foxgloveQueue how many messages may wait for each viewer before new ones are dropped
     */
    /**
     * @param observationWait how long forwarding may wait for a stuck observation (0: best effort, never)
     * @param breaks          robot data breakpoints (empty: none, and the robots are never held)
     * @param breakWait       how long a breakpoint's message waits before it goes on to the program
     */
    record Options(List<Route> routes, @Nullable Path log, Duration upstreamGrace, @Nullable InetSocketAddress foxglove, int foxgloveQueue,
            Duration observationWait, List<StreamCondition> breaks, Duration breakWait) {
        Options {
            breaks = List.copyOf(breaks);
        }
    }

    /** Opens the spy log's writer (for tests: one on a disk that fills up). */
    @FunctionalInterface
    interface LogOpener {
        SpyLogWriter open(Path file, Map<String, String> metadata) throws IOException;
    }

    private final Function<FoxgloveSink, Consumer<StreamMessage>> liveConverter;
    private final LogOpener logOpener;

    SpyCommand() {
        this(FOXGLOVE_SCENE);
    }

    /** For tests: another converter for the live view. */
    SpyCommand(Function<FoxgloveSink, Consumer<StreamMessage>> liveConverter) {
        this(liveConverter, SpyLogWriter::create);
    }

    /** For tests: another converter for the live view, another way to open the log. */
    SpyCommand(Function<FoxgloveSink, Consumer<StreamMessage>> liveConverter, LogOpener logOpener) {
        this.liveConverter = liveConverter;
        this.logOpener = logOpener;
    }

    int run(String[] args, PrintStream out, PrintStream err) {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            err.println("stagecraft spy: " + e.getMessage());
            err.println(USAGE);
            return ExitCode.USAGE;
        }
        // Ctrl-C (SIGINT) and SIGTERM run the shutdown hooks: ours asks serve() to stop and waits
        // until the log is closed. A JVM ending on a signal exits with 128 + the signal (130, 143)
        // whatever its hooks do, unless a hook halts it with a status of its own: a stop on request
        // that closed everything cleanly is a success, so the hook halts with serve()'s status.
        // (Catching the signals themselves needs sun.misc.Signal, an unsupported API that this
        // OSGi bundle would have to import from jdk.unsupported.) Nothing else in this JVM needs
        // its hooks: the log is closed and the streams are flushed before the halt.
        CountDownLatch stop = new CountDownLatch(1);
        CountDownLatch cleanedUp = new CountDownLatch(1);
        AtomicInteger status = new AtomicInteger(1);
        Thread hook = new Thread(() -> {
            stop.countDown();
            try {
                if (cleanedUp.await(30, TimeUnit.SECONDS)) {
                    out.flush();
                    err.flush();
                    Runtime.getRuntime().halt(status.get());
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "stagecraft-spy-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            status.set(serve(o, err, stop, System.console() != null, System.in));
            return status.get();
        } finally {
            cleanedUp.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook); // stopped otherwise: the hook has nothing to do
            } catch (IllegalStateException shuttingDown) {
                // a signal stopped us: the hook is running and ends the JVM with our status
            }
        }
    }

    /**
     * Runs the spy until {@code stop} opens, printing the summary line every second (overwriting it
     * on a terminal), then closes the spy, drains the pipeline and closes the log.
     */
    int serve(Options o, PrintStream err, CountDownLatch stop, boolean tty) {
        return serve(o, err, stop, tty, InputStream.nullInputStream());
    }

    /** As {@link #serve(Options, PrintStream, CountDownLatch, boolean)}; a line on {@code keys} releases a breakpoint's hold. */
    int serve(Options o, PrintStream err, CountDownLatch stop, boolean tty, InputStream keys) {
        NetworkSpy spy = new NetworkSpy(o.routes(), WireObserver.NONE).upstreamGrace(o.upstreamGrace());
        BreakConsole breaks = o.breaks().isEmpty() ? null : new BreakConsole(spy, o.breaks(), o.breakWait(), err, tty);
        // Player refusing, or observation failing, is said at once, on its own line (after the live line on a terminal).
        SpyListener say = n -> err.print((tty ? "\n" : "") + "stagecraft spy: " + n.text() + (tty ? "" : "\n"));
        spy.addListener(say);
        // Bind first: a port in use must not leave an empty log behind (or truncate an old one).
        try {
            spy.bind();
        } catch (IOException e) {
            err.println("stagecraft spy: " + e.getMessage());
            spy.close();
            return ExitCode.FAILED;
        }
        // The Foxglove server too, before the log: a port in use must not leave an empty log either.
        FoxgloveServer foxglove = null;
        InetSocketAddress foxgloveAddress = o.foxglove();
        if (foxgloveAddress != null) {
            try {
                foxglove = FoxgloveServer.start(foxgloveAddress, "Stagecraft spy", o.foxgloveQueue());
            } catch (IOException e) {
                err.println("stagecraft spy: " + e.getMessage());
                spy.close();
                return ExitCode.FAILED;
            }
            foxglove.onNotice(n -> err.print((tty ? "\n" : "") + "stagecraft spy: foxglove: " + n + (tty ? "" : "\n")));
        }
        LogRecorder recorder = null;
        Path log = o.log();
        if (log != null) {
            try {
                Map<String, String> meta = new LinkedHashMap<>();
                meta.put("tool", "stagecraft spy");
                meta.put("routes", o.routes().toString());
                recorder = new LogRecorder(logOpener.open(log, meta));
            } catch (IOException e) {
                err.println("stagecraft spy: cannot write the log " + log + ": " + LogFileProblem.reason(log, e));
                spy.close();
                if (foxglove != null) {
                    foxglove.close();
                }
                return ExitCode.FAILED;
            }
        }
        StreamBus bus = new StreamBus();
        // The converter runs on the bus's delivery (one message at a time), never on the spy's threads.
        Live live = foxglove == null ? null
                : new Live(foxglove, BusRelay.start(bus, foxglove, liveConverter, BusRelay.DEFAULT_CAPACITY));
        // with a live view, the recorder hook also tells it when a connection has ended
        ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()),
                live != null ? new EndOfConnections(recorder, bus) : recorder, ObservationPipeline.DEFAULT_MAX_QUEUED_BYTES)
                .observationWait(o.observationWait());
        pipeline.addListener(say);
        spy.observer(pipeline);
        try {
            spy.start();
        } catch (IOException e) {
            err.println("stagecraft spy: " + e.getMessage());
            stop(spy, pipeline, live, bus);
            return ExitCode.FAILED;
        }
        for (int i = 0; i < o.routes().size(); i++) {
            InetSocketAddress a = spy.boundAddresses().get(i);
            err.println("spying " + a.getAddress().getHostAddress() + ":" + a.getPort() + " -> "
                    + o.routes().get(i).upstream().getHostString() + ":" + o.routes().get(i).upstream().getPort());
        }
        if (o.log() != null) {
            err.println("logging to " + o.log());
        }
        if (live != null) {
            err.println("serving Foxglove on " + live.server().uri()
                    + (o.foxglove().getAddress().isAnyLocalAddress() ? " (all interfaces)" : ""));
        }
        if (breaks != null) {
            breaks.start(keys);
        }
        Summary summary = new Summary(spy, pipeline, live, breaks);
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
        stop(spy, pipeline, live, bus);
        err.println((tty ? "\n" : "") + "stopped: " + summary.totals());
        // the wire was relayed whole; a log that stopped early lacks part of it (the line above says how much)
        return pipeline.recorderError() != null ? ExitCode.LOSSES : ExitCode.DONE;
    }

    /** The live view: the Foxglove server and the relay that feeds it from the bus. */
    record Live(FoxgloveServer server, BusRelay relay) {
        /**
         * Viewers (connected now, or since the start for the totals) and what was not shown live: frames a
         * viewer was too slow for, bus messages the converter was too slow for.
         */
        String summary(boolean totals) {
            FoxgloveServer.Counters c = server.counters();
            return String.format(Locale.ROOT, "foxglove %d viewers%s, %d dropped, %d not converted",
                    totals ? c.viewersServed() : c.viewers(), totals ? " served" : "", c.framesDropped(), relay.dropped());
        }
    }

    private static void stop(NetworkSpy spy, ObservationPipeline pipeline, @Nullable Live live, StreamBus bus) {
        spy.close();
        try {
            pipeline.close();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (live != null) {
            live.relay().awaitIdle(Duration.ofSeconds(10)); // what the spy saw before the stop still reaches the viewers
            live.relay().close();
            live.server().close();
        }
        bus.close();
    }

    static Options parse(String[] args) {
        List<Route> routes = new ArrayList<>();
        String bind = Route.DEFAULT_BIND;
        Path log = null;
        String foxglove = null;
        int foxgloveQueue = FoxgloveServer.DEFAULT_MAX_QUEUED_FRAMES;
        Duration grace = NetworkSpy.DEFAULT_UPSTREAM_GRACE;
        Duration observationWait = ObservationPipeline.DEFAULT_OBSERVATION_WAIT;
        List<StreamCondition> breaks = new ArrayList<>();
        Duration breakWait = Duration.ZERO;
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
                case "--upstream-grace" -> grace = seconds(a, v);
                case "--observation-wait" -> observationWait = seconds(a, v);
                case "--foxglove" -> foxglove = v;
                case "--foxglove-queue" -> foxgloveQueue = count(a, v);
                case "--break" -> breaks.add(breakpoint(v));
                case "--break-wait" -> breakWait = seconds(a, v);
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
        InetSocketAddress live = null;
        if (foxglove != null) {
            try {
                live = Route.address(foxglove, bind); // a bare port listens where the spy does (--bind)
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("--foxglove: " + e.getMessage(), e);
            }
        }
        return new Options(routes, log, grace, live, foxgloveQueue, observationWait, breaks, breakWait);
    }

    private static StreamCondition breakpoint(String text) {
        try {
            return StreamCondition.parse(text, CodecRegistry.standard());
        } catch (ConditionException e) {
            throw new IllegalArgumentException("--break " + e.getMessage() + "\n  " + e.pointer().replace("\n", "\n  "), e);
        }
    }

    private static int count(String option, String text) {
        try {
            int n = Integer.parseInt(text);
            if (n >= 1 && n <= 1_000_000) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException(option + " '" + text + "' is not a number of messages 1..1000000");
    }

    private static Duration seconds(String option, String text) {
        double s;
        try {
            s = Double.parseDouble(text);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " '" + text + "' is not a number of seconds", e);
        }
        if (!(s >= 0) || s > 3600) {
            throw new IllegalArgumentException(option + " " + text + " is not 0..3600 seconds");
        }
        return Duration.ofNanos(Math.round(s * 1e9));
    }

    /** The live one-line summary: rates since the previous line, totals since the start. */
    private static final class Summary {
        private final NetworkSpy spy;
        private final ObservationPipeline pipeline;
        private final @Nullable Live live;
        private final @Nullable BreakConsole breaks;
        private long lastMessages;
        private long lastBytes;
        private long lastNanos = System.nanoTime();

        Summary(NetworkSpy spy, ObservationPipeline pipeline, @Nullable Live live, @Nullable BreakConsole breaks) {
            this.spy = spy;
            this.pipeline = pipeline;
            this.live = live;
            this.breaks = breaks;
        }

        String next() {
            long now = System.nanoTime();
            double secs = Math.max(1e-3, (now - lastNanos) / 1e9);
            long messages = pipeline.messages();
            long bytes = spy.bytesForwarded(Direction.CLIENT_TO_SERVER) + spy.bytesForwarded(Direction.SERVER_TO_CLIENT);
            String line = String.format(Locale.ROOT,
                    "connections %d open/%d | %.0f msg/s | %.1f kB/s | undecodable %d msg | unframed %d B | unobserved %d B%s%s%s%s",
                    spy.openConnections(), spy.totalConnections(), (messages - lastMessages) / secs,
                    (bytes - lastBytes) / secs / 1000, pipeline.decodeProblems(), pipeline.unframedBytes(),
                    pipeline.droppedBytes(), failures(" | "), live != null ? " | " + live.summary(false) : "",
                    pipeline.recorderError() != null ? " | " + pipeline.recorderError() : "",
                    breaks != null ? " | " + breaks.status() : "");
            lastMessages = messages;
            lastBytes = bytes;
            lastNanos = now;
            return line;
        }

        String totals() {
            return String.format(Locale.ROOT,
                    "%d connections, %d messages, %d bytes forwarded, %d undecodable messages, %d unframed bytes,"
                            + " %d bytes unobserved%s%s%s%s",
                    spy.totalConnections(), pipeline.messages(),
                    spy.bytesForwarded(Direction.CLIENT_TO_SERVER) + spy.bytesForwarded(Direction.SERVER_TO_CLIENT),
                    pipeline.decodeProblems(), pipeline.unframedBytes(), pipeline.droppedBytes(), failures("; "),
                    live != null ? "; " + live.summary(true) : "",
                    pipeline.recorderError() != null ? "; " + pipeline.recorderError() : "",
                    breaks != null ? "; " + breaks.totals() : "");
        }

        /**
         * What went wrong on the observation side, if anything: messages given up to bound memory,
         * failures of observation (the first one named), failures of the relay's observer calls.
         */
        private String failures(String sep) {
            StringBuilder b = new StringBuilder();
            if (pipeline.abandonedMessages() > 0) {
                b.append(sep).append(pipeline.abandonedMessages()).append(" unfinished messages given up (memory bound)");
            }
            b.append(pipeline.waitingSummary(sep));
            long failed = pipeline.internalErrors() + spy.observerFailures();
            if (failed > 0) {
                b.append(sep).append(failed).append(" observation failures");
                if (pipeline.failure() != null) {
                    b.append(", the first: ").append(pipeline.failure());
                }
            }
            return b.toString();
        }
    }
}
