package org.stagecraft.tools.ui.launch;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.debug.core.DebugException;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.proxy.SpyNotice;
import org.stagecraft.streams.Subscription;
import org.stagecraft.tools.process.SupervisedTool;
import org.stagecraft.tools.process.ToolListener;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.ui.console.SessionPartProcess;
import org.stagecraft.tools.ui.view.ToolsModel;

/**
 * The Eclipse face of one running Robot Session: a process (and so a console) in the launch for
 * every part as soon as it starts, the Tools view's rows, the Error Log for crashes, restarts and
 * failures, and the session's stop when any of its parts is terminated.
 */
public final class SessionParts implements ToolListener {
    public static final String SPY_PART = "Network Spy";
    /** Said of the spy's row: its PID is the workbench's own, for it runs in the workbench's process. */
    public static final String INSIDE_THE_WORKBENCH = " (runs inside the workbench: its PID is the workbench's)";
    /** The Tools view's row for the session as a whole. */
    public static final String SESSION_PART = "Session";
    private static final String BUNDLE = "org.stagecraft.tools.ui";

    private final ILaunch launch;
    private final String sessionName;
    private final Map<String, SessionPartProcess> parts = new LinkedHashMap<>();
    private final List<ILaunch> linkedLaunches = new ArrayList<>();
    private volatile @Nullable RobotSession session;
    private @Nullable SessionPartProcess spy;
    private boolean stopping;
    /** Why the session failed (Player gone for good), or null. */
    private volatile @Nullable String failure;
    /** The session's bus republished on the workbench bus, where the Robot Views listen. */
    private volatile @Nullable Subscription toWorkbench;
    /** The robot hold's IDE wiring (debugger suspend, emergency stop, Tools view), once started. */
    private volatile @Nullable SessionHolds holds;

    public SessionParts(ILaunch launch, String sessionName) {
        this.launch = launch;
        this.sessionName = sessionName;
    }

    public String sessionName() {
        return sessionName;
    }

    /** The session's launch. */
    public ILaunch launch() {
        return launch;
    }

    /** The spy's row once it stopped: e.g. "1 connection relayed". */
    public static String relayed(long connections) {
        return connections + (connections == 1 ? " connection relayed" : " connections relayed");
    }

    /** Whether the session is being stopped (or has been), on request or because it failed. */
    public synchronized boolean isStopping() {
        return stopping;
    }

    public @Nullable RobotSession session() {
        return session;
    }

    /** The process of a part ("Player", a tool's name, {@value #SPY_PART}), or null. */
    public synchronized @Nullable SessionPartProcess part(String name) {
        return parts.get(name);
    }

    /** Called once the session runs: shows the spy as a part of its own. */
    public void started(RobotSession s) {
        this.session = s;
        toWorkbench = WorkbenchBus.forward(Objects.requireNonNull(s.bus())); // a running session has its bus
        // stopped when this plug-in stops at the latest (else Player would outlive the IDE and keep its ports)
        RunningSessions.add(this);
        SessionPartProcess p;
        synchronized (this) {
            p = new SessionPartProcess(SPY_PART, "stagecraft.spy", launch, control(null));
            parts.put(SPY_PART, p);
            spy = p;
        }
        p.register();
        s.portMap().forEach((orig, moved) -> p.stdout("robot programs connect to " + s.config().bindHost() + ":" + orig
                + "  ->  Player on 127.0.0.1:" + moved));
        p.stdout(s.config().log() != null ? "logging to " + s.config().log() : "not logging (no log folder set)");
        ToolsModel.get().update(new ToolsModel.Row(sessionName, SPY_PART, ToolState.READY, ProcessHandle.current().pid(), 0,
                null, "spying on " + s.portMap().keySet() + INSIDE_THE_WORKBENCH));
        ToolsModel.get().update(new ToolsModel.Row(sessionName, SESSION_PART, ToolState.READY, -1, 0, null, "running"));
        holds = SessionHolds.attach(this, s);
        s.failed().thenAccept(this::sessionFailed);
        s.spy().addListener(n -> spyNotice(p, n));
        s.pipeline().addListener(n -> spyNotice(p, n)); // observation failing: the wire goes on, what is shown is incomplete
    }

    /**
     * Player refusing a robot program's connection, or the spy's observation failing: said in the
     * spy's console at once, shown in the Tools view's row and, when something was lost (the
     * program's connection, or what the spy observes), in the Error Log; the log and the bus have it
     * too, but nobody watches those for it.
     */
    private void spyNotice(SessionPartProcess p, SpyNotice n) {
        if (!n.kind().isFailure()) {
            p.stdout("[stagecraft] " + n.text());
            return;
        }
        p.stderr("[stagecraft] " + n.text());
        log(Status.error(sessionName + ": " + n.text()));
        ToolsModel.get().update(new ToolsModel.Row(sessionName, SPY_PART, ToolState.READY, ProcessHandle.current().pid(), 0,
                null, n.text()));
    }

    /**
     * Player is gone for good: the session is failed everywhere a user looks (Tools view, Error Log,
     * the launch and its processes, which end with a non-zero exit value), and what is left of it stops.
     */
    private void sessionFailed(String reason) {
        failure = reason;
        log(Status.error(sessionName + ": session failed: " + reason));
        ToolsModel.get().update(new ToolsModel.Row(sessionName, SESSION_PART, ToolState.FAILED, -1, 0, null, reason));
        SessionPartProcess p = spy;
        if (p != null) {
            p.stderr("[stagecraft] session failed: " + reason);
        }
        stopInBackground();
    }

    /** Why the session failed, or null if it has not. */
    public @Nullable String failure() {
        return failure;
    }

    /** The robot program ran in a launch of its own (PyDev): it ends with the session. */
    public void link(ILaunch other) {
        synchronized (this) {
            linkedLaunches.add(other);
        }
        SessionHolds h = holds;
        if (h != null) {
            h.linked(other); // its program may be suspended already
        }
    }

    /** The session's own launch and the launches linked to it. */
    public synchronized List<ILaunch> launches() {
        List<ILaunch> all = new ArrayList<>(linkedLaunches.size() + 1);
        all.add(launch);
        all.addAll(linkedLaunches);
        return all;
    }

    /** A line of Stagecraft's own in the spy's console, e.g. what a robot data breakpoint did. */
    public void spyConsole(String line) {
        SessionPartProcess p = spy;
        if (p != null) {
            p.stdout("[stagecraft] " + line);
        }
    }

    /**
     * What the Network Spy's line in the Debug view says beside its name, e.g. "stopped: laser:0 min(ranges) =
     * 0.287 m < 0.3" while a robot data breakpoint's hit holds the program ("" to clear it).
     */
    public void spyStatus(String text) {
        SessionPartProcess p = spy;
        if (p != null) {
            p.status(text);
        }
    }

    /** The session's robot hold in the IDE (null until the session runs). */
    public @Nullable SessionHolds holds() {
        return holds;
    }

    @Override
    public void output(@Nullable SupervisedTool tool, Stream stream, String line) {
        if (tool == null) {
            log(Status.warning(sessionName + ": " + line));
            return;
        }
        SessionPartProcess p = partFor(tool);
        switch (stream) {
            case STDERR -> p.stderr(line);
            case SUPERVISOR -> p.stdout("[stagecraft] " + line);
            default -> p.stdout(line);
        }
    }

    @Override
    public void stateChanged(SupervisedTool tool, ToolState from, ToolState to, String detail) {
        SessionPartProcess p = partFor(tool);
        ProcessHandle h = tool.process();
        ToolsModel.get().update(new ToolsModel.Row(sessionName, tool.name(), to, h != null ? h.pid() : -1,
                tool.restarts(), tool.lastExitCode(), detail));
        switch (to) {
            case RESTARTING -> log(Status.warning(sessionName + ": " + tool.name() + " " + detail));
            case FAILED -> log(Status.error(sessionName + ": " + tool.name() + " failed: " + detail));
            default -> {
            }
        }
        if (to.isFinal()) {
            Integer code = tool.lastExitCode();
            p.ended(code != null ? code : 0);
        }
    }

    private synchronized SessionPartProcess partFor(SupervisedTool tool) {
        SessionPartProcess p = parts.get(tool.name());
        if (p == null) {
            p = new SessionPartProcess(tool.name(), "stagecraft.tool", launch, control(tool));
            parts.put(tool.name(), p);
            p.register();
        }
        return p;
    }

    private SessionPartProcess.Control control(@Nullable SupervisedTool tool) {
        return new SessionPartProcess.Control() {
            @Override
            public void terminate() {
                stopInBackground();
            }

            @Override
            public void write(String input) throws IOException {
                if (tool == null) {
                    throw new IOException(SPY_PART + " reads no input");
                }
                tool.write(input);
            }
        };
    }

    /**
     * Stops the whole session (every part depends on the others) without blocking the caller, which
     * is often the UI thread: stopping waits for process trees to end and the log to be written.
     */
    public void stopInBackground() {
        synchronized (this) {
            if (stopping) {
                return;
            }
            stopping = true;
        }
        Thread.ofVirtual().name("stagecraft-session-stop").start(this::stopNow);
    }

    /** Stops everything and marks every part ended. */
    public void stopNow() {
        SessionHolds h = holds;
        if (h != null) {
            h.close();
        }
        List<ILaunch> others;
        synchronized (this) {
            stopping = true;
            others = List.copyOf(linkedLaunches);
        }
        for (ILaunch l : others) {
            try {
                if (l.canTerminate()) {
                    l.terminate();
                }
            } catch (DebugException e) {
                log(Status.warning(sessionName + ": could not stop " + l.getLaunchConfiguration().getName(), e));
            }
        }
        RobotSession s = session;
        if (s != null) {
            s.close();
            Subscription forwarding = toWorkbench;
            if (forwarding != null) {
                forwarding.close();
            }
            RunningSessions.remove(this);
            if (spy != null) {
                spy.stdout("stopped: " + s.spy().totalConnections() + " connections, " + s.pipeline().messages()
                        + " messages, " + (s.spy().bytesForwarded(Direction.CLIENT_TO_SERVER)
                                + s.spy().bytesForwarded(Direction.SERVER_TO_CLIENT)) + " bytes relayed, "
                        + s.pipeline().droppedBytes() + " bytes unobserved"
                        + s.pipeline().waitingSummary("; ")
                        + (s.pipeline().internalErrors() > 0 ? "; " + s.pipeline().internalErrors() + " observation failures" : "")
                        + (s.pipeline().recorderError() != null ? "; " + s.pipeline().recorderError() : ""));
                ToolsModel.get().update(new ToolsModel.Row(sessionName, SPY_PART, ToolState.STOPPED, -1, 0, null,
                        relayed(s.spy().totalConnections())));
            }
            if (failure == null) {
                ToolsModel.get().update(new ToolsModel.Row(sessionName, SESSION_PART, ToolState.STOPPED, -1, 0, null,
                        "stopped"));
            }
        }
        List<SessionPartProcess> all;
        synchronized (this) {
            all = List.copyOf(parts.values());
        }
        int exit = failure != null ? 1 : 0;
        for (SessionPartProcess p : all) {
            p.ended(exit);
        }
    }

    /** The session could not start: every part shown so far ends, and the reason goes to the Error Log. */
    public void failed(String message, @Nullable Throwable cause) {
        log(Status.error(sessionName + ": " + message, cause));
        List<SessionPartProcess> all;
        synchronized (this) {
            all = List.copyOf(parts.values());
        }
        for (SessionPartProcess p : all) {
            p.stderr("[stagecraft] session not started: " + message);
            p.ended(1);
        }
    }

    static void log(org.eclipse.core.runtime.IStatus status) {
        ILog.of(Platform.getBundle(BUNDLE)).log(status);
    }
}
