package org.stagecraft.tools.ui.launch;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import org.eclipse.core.runtime.Status;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.process.ProcessTree;
import org.stagecraft.tools.process.SupervisedTool;
import org.stagecraft.tools.session.RobotSession;

/**
 * The Robot Sessions running in this IDE, so that they are stopped while the plug-ins they need are
 * still there.
 * <p>
 * The orderly way is {@link #stopAll()}, called by this plug-in's activator when it stops (at the
 * latest when the IDE exits; OSGi stops this plug-in before the ones it requires). A JVM shutdown
 * hook stays as the last resort for an exit that skips the plug-ins' stop (System.exit from
 * elsewhere, SIGTERM): by the time it runs the plug-ins may be stopped and their class loaders gone,
 * so it only kills the tools' process trees, using classes loaded when the first session started,
 * and does nothing when no session runs. (Should the JVM die without even running hooks, the
 * {@link org.stagecraft.tools.process.OrphanReaper} takes the tools down.)
 */
public final class RunningSessions {
    private static final Duration LAST_RESORT_GRACE = Duration.ofSeconds(2);
    private static final Set<SessionParts> RUNNING = ConcurrentHashMap.newKeySet();
    private static @Nullable Thread lastResort;

    private RunningSessions() {
    }

    static synchronized void add(SessionParts parts) {
        if (lastResort == null) {
            preloadLastResort();
            lastResort = new Thread(RunningSessions::killLeftovers, "stagecraft-session-exit");
            Runtime.getRuntime().addShutdownHook(lastResort);
        }
        RUNNING.add(parts);
    }

    static void remove(SessionParts parts) {
        RUNNING.remove(parts);
    }

    /** The sessions running now. */
    public static List<SessionParts> running() {
        return List.copyOf(RUNNING);
    }

    /**
     * Stops every running session and waits until each is stopped (processes gone, log closed).
     *
     * @return how many sessions were stopped
     */
    public static int stopAll() {
        List<SessionParts> all = running();
        for (SessionParts parts : all) {
            try {
                parts.stopNow();
            } catch (RuntimeException | LinkageError e) {
                SessionParts.log(Status.error(parts.sessionName() + ": could not stop the session: " + e, e));
            } finally {
                RUNNING.remove(parts);
            }
        }
        return all.size();
    }

    /**
     * The shutdown hook's work: kill what the sessions still run. Only JDK classes and classes loaded in
     * advance ({@link #preloadLastResort()}); no lambdas, whose classes would be made on first use.
     *
     * @return how many processes were stopped
     */
    static int killLeftovers() {
        int killed = 0;
        for (Object o : RUNNING.toArray()) {
            RobotSession s = ((SessionParts) o).session();
            if (s == null) {
                continue;
            }
            List<SupervisedTool> tools = new ArrayList<>(s.tools());
            SupervisedTool player = s.player();
            if (player != null) {
                tools.add(player);
            }
            for (SupervisedTool t : tools) {
                ProcessHandle h = t.process();
                if (h != null && h.isAlive()) {
                    killed += ProcessTree.stop(h, LAST_RESORT_GRACE).size();
                }
            }
        }
        return killed;
    }

    /**
     * Loads, through this plug-in's class loader, every class of ours {@link #killLeftovers()} touches, so
     * that the hook still finds them once OSGi has stopped the plug-ins (java.* classes come from the JDK's
     * loader, which stays).
     */
    private static void preloadLastResort() {
        ClassLoader loader = RunningSessions.class.getClassLoader();
        for (Class<?> c : List.of(ProcessTree.class, SupervisedTool.class, RobotSession.class, SessionParts.class,
                ProcessHandle.class, ArrayList.class, Duration.class)) {
            try {
                Class.forName(c.getName(), true, loader);
            } catch (ClassNotFoundException e) {
                throw new IllegalStateException(e);
            }
        }
    }
}
