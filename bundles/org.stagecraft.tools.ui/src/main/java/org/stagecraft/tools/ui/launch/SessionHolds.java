package org.stagecraft.tools.ui.launch;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;

import org.eclipse.debug.core.ILaunch;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.spy.hold.HoldListener;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.tools.world.WorldFreeze;
import org.stagecraft.tools.world.WorldState;
import org.stagecraft.spy.hold.RobotHold;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.ui.breakpoints.SessionDataBreakpoints;
import org.stagecraft.tools.ui.view.ToolsModel;

/**
 * The robot hold of one running Robot Session in the IDE: the debugger's suspend holds (when the
 * session's option is on), the emergency stop reaches it, and the Tools view's "Session" row says
 * whether and why its robots are held.
 *
 * <p>For tests and other plug-ins: {@link #of(ILaunch)} finds it from the session's launch or from a
 * launch linked to it (the robot program's PyDev launch), and {@link #hold()} is the spy's
 * {@link RobotHold}.
 */
public final class SessionHolds implements AutoCloseable {
    private static final Map<SessionParts, SessionHolds> RUNNING = new ConcurrentHashMap<>();

    private final SessionParts parts;
    private final RobotHold hold;
    private final @Nullable SuspendHold suspend;
    private final @Nullable SessionDataBreakpoints dataBreakpoints;
    private final HoldListener toToolsView = this::show;
    private final @Nullable WorldFreeze world;
    private final WorldFreeze.Listener worldToToolsView = (state, problem) -> show(hold().state());

    private SessionHolds(SessionParts parts, RobotHold hold, @Nullable SuspendHold suspend,
            @Nullable SessionDataBreakpoints dataBreakpoints, @Nullable WorldFreeze world) {
        this.parts = parts;
        this.world = world;
        this.hold = hold;
        this.suspend = suspend;
        this.dataBreakpoints = dataBreakpoints;
    }

    /** Wires a session that has just started (its spy exists). */
    static SessionHolds attach(SessionParts parts, RobotSession session) {
        RobotHold hold = Objects.requireNonNull(session.holds()); // it has just started: its spy exists
        SuspendHold suspend = session.config().spy().holdWhenSuspended()
                ? new SuspendHold(hold, parts::launches).start()
                : null;
        NetworkSpy spy = Objects.requireNonNull(session.spy());
        SessionDataBreakpoints data = spy.dataBreakpoints().isEnabled()
                ? new SessionDataBreakpoints(spy.dataBreakpoints(), parts::launches, parts::spyConsole, parts::spyStatus).start()
                : null;
        WorldFreeze world = session.world();
        SessionHolds h = new SessionHolds(parts, hold, suspend, data, world);
        hold.addListener(h.toToolsView);
        if (world != null) {
            world.addListener(h.worldToToolsView);
        }
        RUNNING.put(parts, h);
        EmergencyStop.get().register(hold);
        h.show(hold.state());
        return h;
    }

    /** The holds of the session that {@code launch} belongs to (its own launch or a linked one), or null. */
    public static @Nullable SessionHolds of(ILaunch launch) {
        for (SessionHolds h : RUNNING.values()) {
            if (h.parts.launches().contains(launch)) {
                return h;
            }
        }
        return null;
    }

    /** Every running session's holds. */
    public static List<SessionHolds> running() {
        return List.copyOf(RUNNING.values());
    }

    public RobotHold hold() {
        return hold;
    }

    public SessionParts parts() {
        return parts;
    }

    /** The debugger listener, or null when the session's "hold while suspended" is off. */
    public @Nullable SuspendHold suspendHold() {
        return suspend;
    }

    /** The workbench's robot data breakpoints on this session's spy, or null when its holds are off. */
    public @Nullable SessionDataBreakpoints dataBreakpoints() {
        return dataBreakpoints;
    }

    /** A launch was linked to the session: its threads may already be suspended. */
    void linked(ILaunch launch) {
        if (suspend != null) {
            suspend.scan(launch);
        }
    }

    /** The Tools view's session row: running, whether the robots are held and why, and whether the world is frozen. */
    private void show(HoldState s) {
        ToolsModel.Row row = ToolsModel.get().find(parts.sessionName(), SessionParts.SESSION_PART);
        if (row != null && row.state() != ToolState.READY) {
            return; // failed or stopped: that is what the row must keep saying
        }
        ToolsModel.get().update(new ToolsModel.Row(parts.sessionName(), SessionParts.SESSION_PART, ToolState.READY, -1, 0,
                null, detail(s) + worldDetail()));
    }

    /** " — world frozen at simulated time 12.300 s" while the world driver holds the world still, else "". */
    private String worldDetail() {
        WorldFreeze w = world;
        WorldState last = w == null ? null : w.last();
        return last != null && last.frozen() ? " — world frozen at simulated time " + last.simTime() : "";
    }

    private static final String HELD = "held — ";

    /** "running" and the hold's status line, e.g. "held — Robots held (suspended in the debugger): …". */
    public static String detail(HoldState s) {
        return (s.held() ? HELD : "running — ") + s.description();
    }

    /** Whether a Tools view row's detail is that of a session with held robots. */
    public static boolean isHeldDetail(String detail) {
        return detail != null && detail.startsWith(HELD);
    }

    /** The session ends: no more holds from the debugger or the emergency stop. */
    @Override
    public void close() {
        RUNNING.remove(parts);
        if (suspend != null) {
            suspend.close();
        }
        if (dataBreakpoints != null) {
            dataBreakpoints.close();
        }
        hold.removeListener(toToolsView);
        if (world != null) {
            world.removeListener(worldToToolsView);
        }
        EmergencyStop.get().unregister(hold);
    }
}
