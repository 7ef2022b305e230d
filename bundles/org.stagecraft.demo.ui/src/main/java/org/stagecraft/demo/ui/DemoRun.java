package org.stagecraft.demo.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.DebugException;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.model.IProcess;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;
import org.osgi.framework.FrameworkUtil;
import org.stagecraft.demo.PlayerChoice;
import org.stagecraft.recording.play.RecordingException;
import org.stagecraft.recording.play.TimedConnection;
import org.stagecraft.recording.play.TimedRecording;
import org.stagecraft.tools.process.ToolState;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.ui.launch.ExitWithRunningSessions;
import org.stagecraft.tools.ui.launch.RobotSessionLaunchDelegate;
import org.stagecraft.tools.ui.launch.SessionParts;
import org.stagecraft.tools.ui.view.ToolsModel;
import org.stagecraft.views.RobotView;

/**
 * One run of the demo: the project, the launch configuration, the views, the launch, the Session
 * Log, then status samples until the workbench closes (by the user, or after {@code exitAfter}).
 * Preparing and launching run in a job (they wait for files and processes); everything that touches
 * widgets runs on the UI thread.
 */
final class DemoRun {
    private static final int SAMPLE_MILLIS = 1000;

    private final DemoOptions options;
    private final Display display;
    private final DemoStatus status;
    private volatile List<RobotView> views = List.of();
    private volatile @Nullable Path spyLog;
    private volatile @Nullable ILaunch launch;
    private volatile boolean failed;
    private final PartReports reports = new PartReports();

    DemoRun(DemoOptions options, Display display) {
        this.options = options;
        this.display = display;
        Path file = options.status() != null ? options.status() : stateLocation().resolve("status.json");
        this.status = new DemoStatus(file);
        DemoLog.info("status in " + file);
    }

    void start() {
        if (options.exitAfterSeconds() > 0) {
            display.asyncExec(() -> display.timerExec(options.exitAfterSeconds() * 1000, this::finishAndExit));
        }
        Job job = Job.create("Starting the Stagecraft demo", this::prepareAndLaunch);
        job.schedule();
    }

    private IStatus prepareAndLaunch(IProgressMonitor monitor) {
        try {
            status.put("phase", "preparing");
            IProject project = DemoProject.install(monitor);
            status.put("project", project.getLocation().toString());
            Path chosen = options.recording();
            Path recording = chosen != null ? chosen : project.getFile(DemoProject.RECORDING).getLocation().toPath();
            TimedRecording rec = TimedRecording.read(recording);
            DemoLog.info(String.format(Locale.ROOT, "recording %s: %d connection(s), %.1f s", recording,
                    rec.connections().size(), rec.connections().stream().mapToDouble(TimedConnection::length).max().orElse(0)));
            PlayerChoice player = PlayerChoice.choose(options.player(), RecordedPrograms.writePlayerLauncher(stateLocation()),
                    System.getenv("PATH"));
            status.put("player", player.program());
            status.put("recordedPlayer", player.recorded());
            DemoLog.info(player.recorded() ? "Player: the recorded Player (" + player.program() + ")"
                    : "Player: " + player.program() + " (a real Player/Stage)");
            status.put("robotProgram", player.recorded() ? RecordedPrograms.ROBOT_TOOL : DemoLaunch.STROLL);
            ILaunchConfiguration config = DemoLaunch.configure(project, player, recording, options.python());
            DemoEditors.keepConsolesBehind();

            display.syncExec(this::openViews);
            status.put("phase", "launching");
            ILaunch launch = DemoLaunch.launch(config, monitor);
            this.launch = launch;
            SessionParts parts = RobotSessionLaunchDelegate.partsOf(launch);
            if (parts == null || parts.session() == null) {
                fail("the Robot Session '" + config.getName() + "' ended as soon as it started", null);
                return Status.OK_STATUS;
            }
            reports.listen(parts, RobotSession.PLAYER_TOOL_NAME, player.recorded()
                    ? new String[] {RecordedPrograms.ROBOT_TOOL, RobotSession.PLAYER_TOOL_NAME} : new String[0]);
            // Player gone for good (crashed, killed): the session failed, and so did the demo
            // (async: the session's own handler, which marks it FAILED in the Tools view, runs on the
            // completing thread, possibly after ours; the status should show what the view shows)
            parts.session().failed().thenAcceptAsync(reason -> {
                awaitFailedInToolsView(parts);
                if (!PlatformUI.getWorkbench().isClosing()) {
                    fail("the Robot Session '" + config.getName() + "' failed: " + reason, null);
                }
            });
            spyLog = parts.session().config().log();
            status.put("spyLog", spyLog == null ? null : spyLog.toString());
            synchronized (this) {
                if (!failed) {
                    status.put("phase", "running");
                }
            }
            DemoLog.info("Robot Session '" + config.getName() + "' runs; spy log " + spyLog);
            IFolder logs = project.getFolder(DemoProject.LOG_FOLDER);
            logs.refreshLocal(IResource.DEPTH_ONE, monitor);
            IFile logFile = spyLog == null ? null : logs.getFile(spyLog.getFileName().toString());
            IFile cfgFile = project.getFile(DemoProject.CFG);
            display.asyncExec(() -> {
                status.put("sessionLogEditor", DemoEditors.open(window().getActivePage(), cfgFile, logFile));
                sampleEverySecond();
            });
        } catch (RecordingException e) {
            fail("the demo recording cannot be used: " + e.getMessage(), e);
        } catch (CoreException e) {
            fail(e.getStatus().getMessage(), e);
        } catch (Exception e) {
            fail(e.toString(), e);
        }
        return Status.OK_STATUS;
    }

    /** Waits (at most 5 s) until the session's own failure handler has marked it FAILED in the Tools view. */
    private static void awaitFailedInToolsView(SessionParts parts) {
        long end = System.nanoTime() + 5_000_000_000L;
        while (System.nanoTime() < end && !(parts.failure() != null && ToolsModel.get().rows().stream()
                .anyMatch(r -> r.session().equals(parts.sessionName()) && r.part().equals(SessionParts.SESSION_PART)
                        && r.state() == ToolState.FAILED))) {
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    /** The launch's processes (the session's parts and the robot program): label, and exit value once ended. */
    private List<Map<String, Object>> processes() {
        ILaunch l = launch;
        List<Map<String, Object>> out = new ArrayList<>();
        if (l == null) {
            return out;
        }
        for (IProcess p : l.getProcesses()) {
            Map<String, @Nullable Object> m = new LinkedHashMap<>();
            m.put("label", p.getLabel());
            m.put("terminated", p.isTerminated());
            if (p.isTerminated()) {
                try {
                    m.put("exitValue", p.getExitValue());
                } catch (DebugException e) {
                    m.put("exitValue", null);
                }
            }
            out.add(m);
        }
        return out;
    }

    private void openViews() {
        try {
            views = DemoViews.open(window());
        } catch (Exception e) {
            DemoLog.error("cannot open the demo's views: " + e.getMessage(), e);
        }
    }

    private void sampleEverySecond() {
        if (display.isDisposed() || PlatformUI.getWorkbench().isClosing()) {
            return;
        }
        status.put("reports", reports.lines());
        status.put("playerConsole", reports.console());
        status.put("processes", processes());
        status.sample(views, spyLog);
        if (failed) {
            return; // the failure's sample is taken; the workbench closes or shows the error
        }
        display.timerExec(SAMPLE_MILLIS, this::sampleEverySecond);
    }

    private synchronized void fail(String message, @Nullable Throwable cause) {
        if (failed) {
            return;
        }
        failed = true;
        DemoLog.error(message, cause);
        status.put("error", message);
        status.put("phase", "failed");
        // one last sample: the parts' states (the Tools view's rows) and Player's console at the failure
        display.asyncExec(() -> {
            status.put("playerConsole", reports.console());
            status.put("processes", processes());
            status.sample(views, spyLog);
        });
        if (options.exitAfterSeconds() > 0) {
            display.asyncExec(DemoRun::closeUnattended);
        } else {
            display.asyncExec(() -> MessageDialog.openError(window().getShell(), "Stagecraft demo", message));
        }
    }

    private void finishAndExit() {
        if (PlatformUI.getWorkbench().isClosing()) {
            return;
        }
        if (!failed) {
            status.put("reports", reports.lines());
            status.put("playerConsole", reports.console());
            status.put("processes", processes());
            status.finish(views, spyLog);
        }
        DemoLog.info("closing the workbench after " + options.exitAfterSeconds() + " s (--exit-after)");
        closeUnattended();
    }

    /** Closes the workbench with nobody there to answer: the running session is stopped without asking. */
    private static void closeUnattended() {
        System.setProperty(ExitWithRunningSessions.WITHOUT_ASKING, "true");
        PlatformUI.getWorkbench().close();
    }

    private static IWorkbenchWindow window() {
        IWorkbenchWindow w = PlatformUI.getWorkbench().getActiveWorkbenchWindow();
        return w != null ? w : PlatformUI.getWorkbench().getWorkbenchWindows()[0];
    }

    private static Path stateLocation() {
        return Platform.getStateLocation(FrameworkUtil.getBundle(DemoRun.class)).toPath();
    }
}
