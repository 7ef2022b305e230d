package org.stagecraft.tools.session;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.tools.cfg.CfgException;
import org.stagecraft.tools.cfg.CfgRewriter;
import org.stagecraft.tools.cfg.PlayerCfg;
import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.SupervisedTool;
import org.stagecraft.tools.process.ToolException;
import org.stagecraft.tools.process.ToolListener;
import org.stagecraft.tools.process.ToolSpec;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.world.WorldChannel;
import org.stagecraft.tools.world.WorldDriver;
import org.stagecraft.tools.world.WorldException;
import org.stagecraft.tools.world.WorldFreeze;
import org.stagecraft.tools.world.WorldState;

/**
 * One development session against Player, started in the order the parts depend on each other:
 * <ol>
 * <li>read the cfg and find every port Player will listen on; check they are free now (the spy
 * will need them);</li>
 * <li>pick a free port for each, write the rewritten copy of the cfg into a scratch directory;</li>
 * <li>start the user's tools, each until ready;</li>
 * <li>start Player on the copy ({@code -p MOVED copy}) until all moved ports accept connections;</li>
 * <li>start the Network Spy on the original ports, forwarding to the moved ones, logging;</li>
 * <li>when Player runs Stage and the options ask for it, connect to Stagecraft's world driver (added to the
 * copy in step 2, on a port of its own) so that the world freezes while the robots are held.</li>
 * </ol>
 * Robot programs then connect to the original ports, unchanged. If any step fails, what was
 * started is stopped again before the error is thrown: there is no half-started session.
 * {@link #close()} stops everything in reverse order, closes the log and removes the scratch files.
 */
public final class RobotSession implements AutoCloseable {
    public static final String PLAYER_TOOL_NAME = "Player";
    private static final Duration WORLD_ANSWER_WITHIN = Duration.ofSeconds(5);

    private final SessionConfig config;
    private final CodecRegistry codecs;
    private final ToolListener listener;
    private @Nullable PlayerCfg cfg;
    private final Map<Integer, Integer> portMap = new LinkedHashMap<>();
    private @Nullable ScratchDirectory scratch;
    private CfgRewriter.@Nullable Rewritten rewritten;
    private final List<SupervisedTool> tools = new ArrayList<>();
    private @Nullable SupervisedTool player;
    private @Nullable StreamBus bus;
    private @Nullable ObservationPipeline pipeline;
    private @Nullable NetworkSpy spy;
    private @Nullable WorldFreeze world;
    private String worldProblem = "";
    private boolean closed;
    private SessionState state = SessionState.STARTING;
    private final CompletableFuture<String> failed = new CompletableFuture<>();

    private RobotSession(SessionConfig config, CodecRegistry codecs, ToolListener listener) {
        this.config = config;
        this.codecs = Objects.requireNonNull(codecs, "codecs");
        this.listener = listener == null ? ToolListener.NONE : listener;
    }

    /** Passes everything on, and sees Player going down for good while the session runs. */
    private final ToolListener watcher = new ToolListener() {
        @Override
        public void output(@Nullable SupervisedTool tool, Stream stream, String line) {
            listener.output(tool, stream, line);
        }

        @Override
        public void stateChanged(SupervisedTool tool, ToolState from, ToolState to, String detail) {
            listener.stateChanged(tool, from, to, detail);
            // FAILED or EXITED: its restart policy has given up (a stop on request ends STOPPED)
            if (tool == player && (to == ToolState.FAILED || to == ToolState.EXITED)) {
                playerGone(detail);
            }
        }
    };

    /**
     * Starts a session whose spy decodes with Player's standard interfaces ({@link CodecRegistry#standard()}).
     *
     * @throws SessionException naming what failed and where; nothing of the session is left running
     */
    public static RobotSession start(SessionConfig config, ToolListener listener) throws SessionException {
        return start(config, CodecRegistry.standard(), listener);
    }

    /**
     * Starts a session whose spy decodes with {@code codecs} (in the workbench: the standard interfaces
     * plus every contributed decoder).
     *
     * @throws SessionException naming what failed and where; nothing of the session is left running
     */
    public static RobotSession start(SessionConfig config, CodecRegistry codecs, ToolListener listener)
            throws SessionException {
        RobotSession s = new RobotSession(config, codecs, listener);
        try {
            s.startParts();
            return s;
        } catch (SessionException e) {
            s.close();
            throw e;
        } catch (RuntimeException | Error e) {
            s.close();
            throw e;
        }
    }

    private void startParts() throws SessionException {
        PlayerCfg cfg;
        try {
            cfg = PlayerCfg.read(config.cfg());
        } catch (CfgException e) {
            throw new SessionException("bad Player configuration: " + e.getMessage(), e);
        }
        this.cfg = cfg;
        Map<Integer, PlayerCfg.AddressUse> ports = cfg.listenPorts(config.defaultPort());
        if (ports.isEmpty()) {
            throw new SessionException(cfg.file() + ": no driver provides a device, so Player would serve nothing", null);
        }
        for (Map.Entry<Integer, PlayerCfg.AddressUse> p : ports.entrySet()) {
            if (!Ports.isFree(config.bindHost(), p.getKey())) {
                PlayerCfg.AddressUse a = p.getValue();
                String from = a.address().port() < 0 ? "the default port (-p " + config.defaultPort() + ") of \""
                        + a.token().text() + "\" at " + a.where() : "\"" + a.token().text() + "\" at " + a.where();
                throw new SessionException("port " + p.getKey() + " is already in use on " + config.bindHost() + " (needed for "
                        + from + "); is another Player or session running?", null);
            }
        }
        try {
            boolean defaultListed = ports.containsKey(config.defaultPort());
            List<Integer> free = Ports.free("127.0.0.1", ports.size() + (defaultListed ? 0 : 1) + 1);
            int i = 0;
            for (int original : ports.keySet()) {
                portMap.put(original, free.get(i++));
            }
            int movedDefault = defaultListed ? portMap.get(config.defaultPort()) : free.get(i);
            Path scratchRoot = config.scratchRoot();
            scratch = ScratchDirectory.create(scratchRoot != null ? scratchRoot : ScratchDirectory.defaultRoot());
            rewritten = CfgRewriter.write(cfg, portMap, scratch.path());
            int worldPort = addWorldDriver(cfg, rewritten.main(), free.get(free.size() - 1));
            List<Integer> playerPorts = new ArrayList<>(portMap.values());
            if (worldPort > 0) {
                playerPorts.add(worldPort);
            }

            for (ToolSpec t : config.tools()) {
                SupervisedTool tool = new SupervisedTool(t, listener);
                tools.add(tool);
                tool.start();
            }

            List<String> command = new ArrayList<>(config.playerCommand());
            command.addAll(List.of("-p", String.valueOf(movedDefault), rewritten.main().toString()));
            ToolSpec playerSpec = new ToolSpec(PLAYER_TOOL_NAME, command, cfg.file().getParent(), config.playerEnvironment(),
                    Readiness.playerPorts("127.0.0.1", List.copyOf(playerPorts)), config.playerRestart(),
                    config.playerReadyWithin());
            player = new SupervisedTool(playerSpec, watcher);
            player.start();

            startSpy();
            if (worldPort > 0) {
                startWorldFreeze(worldPort);
            }
            synchronized (this) {
                if (state == SessionState.STARTING) {
                    state = SessionState.RUNNING;
                }
            }
            if (player.state().isFinal()) {
                // it went down between its start and now
                playerGone("ended while the session started");
            }
        } catch (CfgException e) {
            throw new SessionException("bad Player configuration: " + e.getMessage(), e);
        } catch (ToolException e) {
            throw new SessionException(e.getMessage(), e);
        } catch (IOException e) {
            throw new SessionException(e.getMessage(), e);
        }
    }

    private void startSpy() throws IOException {
        List<Route> routes = new ArrayList<>();
        for (Map.Entry<Integer, Integer> m : portMap.entrySet()) {
            routes.add(Route.of(config.bindHost(), m.getKey(), "127.0.0.1", m.getValue()));
        }
        StreamBus bus = new StreamBus();
        this.bus = bus;
        LogRecorder recorder = null;
        Path log = config.log();
        if (log != null) {
            Path parent = log.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            Map<String, String> meta = new LinkedHashMap<>();
            meta.put("tool", "stagecraft robot session");
            meta.put("cfg", cfg.file().toString());
            meta.put("routes", routes.toString());
            try {
                recorder = new LogRecorder(SpyLogWriter.create(log, meta));
            } catch (IOException e) {
                throw new IOException("cannot write the spy log " + log + ": " + e.getMessage(), e);
            }
        }
        pipeline = new ObservationPipeline(bus, new PlayerDecoder(codecs), recorder, ObservationPipeline.DEFAULT_MAX_QUEUED_BYTES);
        NetworkSpy spy = new NetworkSpy(routes, pipeline);
        this.spy = spy;
        configureHolds(spy, config.spy());
        spy.start();
    }

    /**
     * Adds Stagecraft's world driver to the copy Player runs on, when the options ask for frozen worlds, holds are
     * on and the cfg runs Stage; builds it first if needed. A driver that cannot be built is no reason to refuse
     * the session: it runs without frozen worlds, and the session's console says why.
     *
     * @return the driver's port, or -1 when there is none
     */
    private int addWorldDriver(PlayerCfg cfg, Path copy, int port) throws IOException {
        SpyOptions o = config.spy();
        if (!o.freezeWorld() || !o.holdsEnabled()) {
            return -1;
        }
        if (!runsStage(cfg)) {
            worldProblem = "Player runs no Stage world here (no \"stage\" driver in " + cfg.file().getFileName() + ")";
            return -1;
        }
        if (!isPlayer(config.playerCommand().get(0))) {
            // a stand-in that reads Player's cfg (the recorded Player of the demo) has no world to freeze
            worldProblem = config.playerCommand().get(0) + " is not Player: no simulated world to freeze";
            return -1;
        }
        try {
            Path library = WorldDriver.build(config.playerCommand().get(0), config.playerEnvironment(), WorldDriver.defaultCache());
            Files.writeString(copy, WorldDriver.cfgSection(library, port), StandardCharsets.UTF_8, StandardOpenOption.APPEND);
            return port;
        } catch (WorldException e) {
            worldProblem = e.getMessage();
            listener.output(null, ToolListener.Stream.SUPERVISOR, "the simulated world will not freeze while robots are held: "
                    + e.getMessage());
            return -1;
        }
    }

    /** Whether the session's Player program is Player itself ({@code player}, by name or path). */
    static boolean isPlayer(String program) {
        Path name = Path.of(program).getFileName();
        return name != null && name.toString().equals("player");
    }

    /** Whether a driver of the cfg is Stage's ({@code name "stage"}). */
    static boolean runsStage(PlayerCfg cfg) {
        for (PlayerCfg.Source s : cfg.sources()) {
            for (PlayerCfg.Entry e : s.entries()) {
                if (e.key().equals("name") && e.values().stream().anyMatch(v -> v.text().equals("stage"))) {
                    return true;
                }
            }
        }
        return false;
    }

    private void startWorldFreeze(int port) {
        NetworkSpy s = Objects.requireNonNull(spy);
        try {
            WorldChannel channel = WorldChannel.open("127.0.0.1", port, WORLD_ANSWER_WITHIN);
            WorldState at = channel.get();
            WorldFreeze w = new WorldFreeze(channel, () -> WorldChannel.open("127.0.0.1", port, WORLD_ANSWER_WITHIN), s,
                    line -> listener.output(null, ToolListener.Stream.SUPERVISOR, line));
            world = w;
            s.holds().addListener(w);
            listener.output(null, ToolListener.Stream.SUPERVISOR, "the simulated world freezes while robots are held (Stage "
                    + (at.gui() ? "with its window" : "without a window") + ", simulated time " + at.simTime() + ")");
        } catch (WorldException e) {
            worldProblem = e.getMessage();
            listener.output(null, ToolListener.Stream.SUPERVISOR, "the simulated world will not freeze while robots are held: "
                    + e.getMessage());
        }
    }

    /**
     * Before {@code start()}: holds and robot data breakpoints only apply to connections accepted while they
     * are enabled, and a robot program may connect the moment the spy listens.
     */
    private static void configureHolds(NetworkSpy spy, SpyOptions options) {
        spy.upstreamGrace(options.upstreamGrace());
        spy.holds().setEnabled(options.holdsEnabled());
        spy.holds().setWatchdog(options.watchdog());
        // a robot data breakpoint holds the robots, so it needs holdable connections too; with no breakpoint
        // set its gate only follows the Player-to-program message boundaries, and holds nothing back
        spy.dataBreakpoints().setEnabled(options.holdsEnabled());
    }

    /**
     * The robot hold of this session's spy (null before the spy exists): what the debugger's
     * suspend and the user's emergency stop act on.
     */
    public @Nullable RobotHold holds() {
        NetworkSpy s = spy;
        return s == null ? null : s.holds();
    }

    public SessionConfig config() {
        return config;
    }

    /**
     * What freezes this session's simulated world while its robots are held, or null when nothing does
     * ({@link #worldProblem()} says why, if the options asked for it).
     */
    public @Nullable WorldFreeze world() {
        return world;
    }

    /** Why the world does not freeze although the options ask for it ("" when it does, or was not asked to). */
    public String worldProblem() {
        return worldProblem;
    }

    public @Nullable PlayerCfg cfg() {
        return cfg;
    }

    /** Original port (where robot programs connect) to the port Player really listens on. */
    public Map<Integer, Integer> portMap() {
        return Collections.unmodifiableMap(portMap);
    }

    /** The copy Player runs on. */
    public CfgRewriter.@Nullable Rewritten rewritten() {
        return rewritten;
    }

    public @Nullable Path scratchDirectory() {
        return scratch == null ? null : scratch.path();
    }

    /** The user's tools in start order. */
    public List<SupervisedTool> tools() {
        return List.copyOf(tools);
    }

    public @Nullable SupervisedTool player() {
        return player;
    }

    public @Nullable NetworkSpy spy() {
        return spy;
    }

    public @Nullable ObservationPipeline pipeline() {
        return pipeline;
    }

    public @Nullable StreamBus bus() {
        return bus;
    }

    public synchronized boolean isClosed() {
        return closed;
    }

    public synchronized SessionState state() {
        return state;
    }

    /**
     * Completes with the reason when the running session fails: Player went down for good (crashed,
     * was killed, or exited, and its restart policy does not start it again). The session's other
     * parts still run until {@link #close()}; whoever shows the session stops it.
     */
    public CompletableFuture<String> failed() {
        return failed;
    }

    private void playerGone(String detail) {
        String reason;
        synchronized (this) {
            if (state != SessionState.RUNNING) {
                return; // failing to start is start()'s error; a close is no failure
            }
            state = SessionState.FAILED;
            reason = "Player is gone (" + detail + "); robot programs have nothing to talk to";
        }
        listener.output(null, ToolListener.Stream.SUPERVISOR, "session failed: " + reason);
        failed.complete(reason);
    }

    /**
     * Stops the spy (closing the log after everything observed is written), Player and the tools
     * (whole process trees, in reverse start order), then removes the scratch files. Safe to call
     * more than once and from any thread.
     */
    @Override
    public synchronized void close() {
        if (closed) {
            return;
        }
        closed = true;
        if (state != SessionState.FAILED) {
            state = SessionState.CLOSED;
        }
        WorldFreeze w = world;
        if (w != null) {
            if (spy != null) {
                spy.holds().removeListener(w);
            }
            w.close(); // a world left frozen would outlive the hold that froze it
        }
        if (spy != null) {
            spy.close();
        }
        if (pipeline != null) {
            try {
                pipeline.close();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        if (bus != null) {
            bus.close();
        }
        if (player != null) {
            player.stop();
        }
        for (int i = tools.size() - 1; i >= 0; i--) {
            tools.get(i).stop();
        }
        if (scratch != null) {
            try {
                scratch.close();
            } catch (IOException e) {
                listener.output(null, ToolListener.Stream.SUPERVISOR, "could not remove " + scratch.path() + ": " + e);
            }
        }
    }
}
