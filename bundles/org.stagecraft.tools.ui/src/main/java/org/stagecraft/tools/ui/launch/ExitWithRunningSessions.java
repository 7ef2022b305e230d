package org.stagecraft.tools.ui.launch;

import java.time.Duration;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchListener;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;

/**
 * Exiting the IDE while Robot Sessions run: the user is asked (as Eclipse asks before exiting with
 * unsaved editors), and the sessions are stopped while the workbench is still whole — their launches
 * end, the debug platform tells its views, the new spy logs appear in their projects — before the
 * workspace is saved. Stopping them only when this plug-in stops came after the display was gone: the
 * debug platform's updates were refused (errors in the log), and the logs' refresh left the workspace
 * changed after its save.
 */
public final class ExitWithRunningSessions implements IWorkbenchListener {
    /** How long exiting waits for the sessions' launches to end and their logs to be shown. */
    static final Duration SETTLE = Duration.ofSeconds(30);

    private final Predicate<List<String>> stopThem;

    /**
     * System property: when "true", exiting stops the running sessions without asking. For closes no
     * user is there to answer: the plug-in tests' harness, the demo's {@code --exit-after}.
     */
    public static final String WITHOUT_ASKING = "stagecraft.exit.stopSessionsWithoutAsking";

    /** Asks the user in a dialog (unless {@link #WITHOUT_ASKING} says not to). */
    public ExitWithRunningSessions() {
        this(sessions -> Boolean.getBoolean(WITHOUT_ASKING) || ask(sessions));
    }

    /** @param stopThem given the running sessions' names, whether to stop them and exit (false: stay) */
    public ExitWithRunningSessions(Predicate<List<String>> stopThem) {
        this.stopThem = stopThem;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public boolean preShutdown(IWorkbench workbench, boolean forced) {
        List<SessionParts> running = RunningSessions.running();
        if (running.isEmpty()) {
            return true;
        }
        if (!forced && !stopThem.test(running.stream().map(SessionParts::sessionName).toList())) {
            return false;
        }
        Display display = Display.getCurrent();
        if (display == null) {
            RunningSessions.stopAll();
            return true;
        }
        // stopped on a thread of its own while the display runs: a part that hands work to the display
        // (a view, a console) while it stops would otherwise wait for the display that waits for it
        Thread stopping = Thread.ofPlatform().name("stagecraft-exit-stop").start(RunningSessions::stopAll);
        // a launch reads as terminated as soon as its parts are, before the debug platform tells its listeners
        // (which schedule the log's refresh): wait for the session's own end as well
        settle(display, () -> stopping.isAlive() || running.stream().anyMatch(p -> !p.launch().isTerminated()
                || RobotSessionLaunchDelegate.partsOf(p.launch()) != null)
                || Job.getJobManager().find(RobotSessionLaunchDelegate.LOG_REFRESH).length > 0);
        return true;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void postShutdown(IWorkbench workbench) {
        // the sessions were stopped before
    }

    /**
     * Runs the display while {@code busy}: the sessions stop, the debug platform ends their launches
     * and the refresh shows their new logs (both post work to the display), within {@link #SETTLE}.
     */
    private static void settle(Display display, BooleanSupplier busy) {
        long deadline = System.nanoTime() + SETTLE.toNanos();
        while (System.nanoTime() < deadline && busy.getAsBoolean()) {
            if (!display.readAndDispatch()) {
                display.timerExec(20, () -> { }); // wake up to look again: the stop and the jobs end off the UI thread
                display.sleep();
            }
        }
    }

    private static boolean ask(List<String> sessions) {
        Display display = Display.getCurrent();
        IWorkbenchWindow window = PlatformUI.getWorkbench().getActiveWorkbenchWindow();
        if (display == null) {
            return true;
        }
        String which = sessions.size() == 1 ? "The Robot Session '" + sessions.get(0) + "' is"
                : sessions.size() + " Robot Sessions are";
        MessageDialog dialog = new MessageDialog(window != null ? window.getShell() : display.getActiveShell(),
                "Robot Sessions Running", null, which + " running. Exiting stops "
                        + (sessions.size() == 1 ? "it" : "them") + ": Player, the tools and the robot program end,"
                        + " the robots are left standing, and each spy log is closed and kept.",
                MessageDialog.QUESTION, 0, "Stop and Exit", "Cancel");
        return dialog.open() == 0;
    }
}
