package org.stagecraft.replay.ui;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.swt.SWT;
import org.eclipse.swt.SWTException;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Label;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.IEditorSite;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.part.EditorPart;
import org.stagecraft.core.streams.BusSources;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.replay.analysis.MessageColumns;
import org.stagecraft.replay.analysis.TimelineDensity;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.play.ReplayClock;
import org.stagecraft.replay.play.ReplayListener;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.replay.ui.internal.EditorInputs;
import org.stagecraft.replay.ui.internal.ExportMenu;
import org.stagecraft.replay.ui.internal.FollowPace;
import org.stagecraft.replay.log.HoldMarks;
import org.stagecraft.replay.ui.internal.InspectorPanel;
import org.stagecraft.replay.ui.internal.LogExport;
import org.stagecraft.replay.ui.internal.SharedLog;
import org.stagecraft.replay.ui.internal.TimelineCanvas;
import org.stagecraft.replay.ui.internal.TransportBar;
import org.stagecraft.replay.ui.internal.UiThrottle;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamProcessors;
import org.stagecraft.views.RobotView;

/**
 * The Session Log editor: opens a spy log, a recorded trace or a Player writelog file
 * ({@link SessionLogs}) and replays it into a stream bus of its own, registered as a
 * {@link BusSources} entry so Robot Views (and anything else on a bus) can follow it exactly as they
 * follow live data. Shows a timeline (a track per stream), the transport and the packet inspector;
 * the Plot view and the export actions work on it.
 *
 * <p>Nothing here holds the log's messages: the timeline is a fixed number of buckets filled by a
 * background pass, the inspector a window read around the replay position. The replay thread only
 * asks for UI updates ({@link UiThrottle}); it never waits for the display. A file that cannot be
 * read completely (truncated, corrupt, still being written) opens with what is readable and says
 * where it stopped; Reload reads it again. Opening and reopening run in a background job; the UI
 * thread only swaps the result in and never waits for a job.
 */
public class SessionLogEditor extends EditorPart {
    public static final String ID = "org.stagecraft.replay.ui.sessionLogEditor";
    /** Timeline resolution: buckets across the whole log, whatever its length. */
    public static final int BUCKETS = 600;
    private static final ILog LOG = ILog.of(Platform.getBundle("org.stagecraft.replay.ui"));
    private static final AtomicInteger VIEWS = new AtomicInteger();
    /** How often a log still being written is looked at, at the most. */
    private static final int FOLLOW_MILLIS = 2000;
    /** The next look at a growing log waits this many times what the last one cost. */
    private static final int FOLLOW_FACTOR = 4;

    private Path file;
    private final MessageColumns columns = new MessageColumns(Contributions.workbench().codecs());
    private final StreamBus bus = new StreamBus();
    private final ExecutorService reader = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "Session Log inspector reader");
        t.setDaemon(true);
        return t;
    });
    private StreamProcessors processors;
    private AutoCloseable source;
    private String sourceId;
    /** The log on show with its readers' hold on it, and its replayer; replaced together, on the UI thread. */
    private volatile SharedLog shared;
    private volatile SessionLog log;
    private volatile Replayer replayer;
    /** Why the file could not be opened at all; why reading it again failed (the previous reading stays). */
    private String openError, reopenError;
    /** What stopped play, told by the replayer; cleared when play starts again. */
    private volatile String playFailure;
    /** The open under way in the background (UI thread only), and the number of the latest one asked for. */
    private Job openJob;
    private long openGeneration;
    private boolean disposed;
    private Job densityJob;
    private volatile TimelineDensity density;

    private TransportBar transport;
    private Label status;
    private TimelineCanvas timeline;
    private InspectorPanel inspector;
    private UiThrottle updates, densityUpdates, statusUpdates;
    private volatile LogMessage lastPublished;
    /** Following a spy log a running spy still writes: its size when last read, and when that look began. */
    private long followedSize = -1;
    private long lastLookNanos;
    private final FollowPace pace = new FollowPace(FOLLOW_MILLIS, FOLLOW_FACTOR);
    private boolean growing;

    @Override
    public void init(IEditorSite site, IEditorInput input) throws PartInitException {
        setSite(site);
        setInput(input);
        file = EditorInputs.path(input);
        if (file == null) {
            throw new PartInitException("The Session Log editor opens local files only, not " + input.getToolTipText());
        }
        setPartName(file.getFileName().toString());
        setTitleToolTip(file.toString());
    }

    @Override
    public void createPartControl(Composite parent) {
        Composite root = new Composite(parent, SWT.NONE);
        GridLayout layout = new GridLayout(1, false);
        layout.marginWidth = layout.marginHeight = 0;
        root.setLayout(layout);
        transport = new TransportBar(root, new Transport());
        transport.control().setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        status = new Label(root, SWT.WRAP);
        status.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        SashForm split = new SashForm(root, SWT.VERTICAL);
        split.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        timeline = new TimelineCanvas(split, this::seek);
        inspector = new InspectorPanel(split, columns, reader, () -> {
            Replayer r = replayer;
            SessionLog l = log;
            return r != null ? r.position() : l != null ? l.startNanos() : 0;
        }, this::inspectorSelected);
        split.setWeights(35, 65);
        installKeys(new Transport());
        updates = new UiThrottle(root.getDisplay(), 50, this::showReplayState);
        densityUpdates = new UiThrottle(root.getDisplay(), 250, this::showDensity);
        statusUpdates = new UiThrottle(root.getDisplay(), 100, this::showStatus);

        SharedWorld.of(bus); // the world model listens from the first message: geometry replies come once
        processors = Contributions.workbench().startProcessors(bus); // derived streams, as on the live bus
        registerSource();
        transport.setEnabled(false);
        startOpen(false);
        root.getDisplay().timerExec(FOLLOW_MILLIS, this::follow);
    }

    /**
     * A spy log without its summary is one the spy is probably still writing (the demo opens its
     * live log): while it grows the editor reads it again in the background, keeping the position and
     * play, so the timeline and inspector fill in as the session runs. A look costs a reopen (a scan of
     * the file) and a timeline pass over it, so the next look waits for the pass to end and at least
     * {@value #FOLLOW_FACTOR} times what both took ({@link FollowPace}). Following ends when the log is
     * complete (the spy closed it) or the editor closes.
     */
    private void follow() {
        if (disposed || timeline.canvas().isDisposed()) {
            return;
        }
        SessionLog l = log;
        if (l != null && l.complete()) {
            growing = false;
            showStatus();
            return; // whole: nothing more will come
        }
        long next = FOLLOW_MILLIS;
        if (openJob == null && !densityRunning()) {
            long waited = (System.nanoTime() - lastLookNanos) / 1_000_000;
            long due = pace.delayMillis();
            if (waited < due) {
                next = due - waited;
            } else {
                long size = fileSize();
                if (size >= 0 && size != followedSize) {
                    growing = true;
                    startOpen(true);
                }
            }
        }
        timeline.canvas().getDisplay().timerExec((int) Math.min(Integer.MAX_VALUE, Math.max(1, next)), this::follow);
    }

    private boolean densityRunning() {
        Job j = densityJob;
        return j != null && j.getState() != Job.NONE;
    }

    private long fileSize() {
        try {
            return Files.size(file);
        } catch (IOException e) {
            return -1;
        }
    }

    /** Whether the editor is following a log that is still being written. */
    public boolean following() {
        return growing;
    }

    /** On the timeline: Space plays or pauses, Left and Right step, Home goes to the start. */
    private void installKeys(TransportBar.Host t) {
        timeline.canvas().addListener(SWT.KeyDown, e -> {
            switch (e.keyCode) {
                case ' ' -> t.playPause();
                case SWT.ARROW_LEFT -> t.stepBack();
                case SWT.ARROW_RIGHT -> t.stepForward();
                case SWT.HOME -> t.toStart();
                default -> {
                    return;
                }
            }
            e.doit = false;
        });
    }

    private void registerSource() {
        String id = "log:" + file.toAbsolutePath();
        for (int n = 2; BusSources.find(id).isPresent(); n++) {
            id = "log:" + file.toAbsolutePath() + "#" + n; // the same file open twice
        }
        sourceId = id;
        source = BusSources.add(new BusSources.Source(id, "Log " + file.getFileName(), bus));
    }

    /**
     * Opens (or reopens) the file in the background: opening may scan a spy log without summary or
     * import a whole trace or writelog file. The editor stays usable on what it shows meanwhile (the
     * status says "reading…"); the new log and its replayer are swapped in on the UI thread
     * ({@link #swapIn}). A newer open supersedes one under way, whose result is closed unseen.
     */
    private void startOpen(boolean followed) {
        long g = ++openGeneration;
        if (openJob != null) {
            openJob.cancel();
        }
        followedSize = fileSize();
        lastLookNanos = System.nanoTime();
        Display display = status.getDisplay();
        Job job = Job.create("Reading " + file.getFileName(), (IProgressMonitor monitor) -> {
            long started = System.nanoTime();
            Opened o = Opened.of(file, columns.registry(), bus);
            long cost = System.nanoTime() - started;
            try {
                display.asyncExec(() -> swapIn(g, o, cost));
            } catch (SWTException gone) {
                o.discard(); // the workbench is closing
            }
            return Status.OK_STATUS;
        });
        job.setSystem(followed); // a first open (perhaps a long import) shows its progress; follow looks do not
        openJob = job;
        job.schedule();
        showStatus();
    }

    /** What a background open produced: the log and its replayer, or why there is none. */
    private record Opened(SharedLog shared, Replayer replayer, Exception error) {
        static Opened of(Path file, CodecRegistry codecs, StreamBus bus) {
            SessionLog l = null;
            try {
                l = SessionLogs.open(file, codecs);
                SharedLog s = new SharedLog(l, (closed, e) -> LOG.warn("Session Log: closing " + closed.path() + ": " + e));
                return new Opened(s, new Replayer(l, bus, ReplayClock.system()), null);
            } catch (IOException | RuntimeException e) {
                if (l != null) {
                    try {
                        l.close();
                    } catch (IOException ignored) {
                        // the open already failed; that is what is reported
                    }
                }
                return new Opened(null, null, e);
            }
        }

        void discard() {
            retire(replayer, shared);
        }
    }

    /**
     * On the UI thread: puts a freshly opened log in place of the one shown. The replay goes on where
     * it was, at the same speed and playing if it played: just after the message last published (so
     * nothing is published again), or at the same time after a seek. The old log is closed in the
     * background once its readers are done.
     */
    private void swapIn(long g, Opened o, long costNanos) {
        if (disposed || g != openGeneration) {
            o.discard(); // superseded, or nobody left to show it
            return;
        }
        openJob = null;
        pace.reopened(costNanos);
        if (o.error() != null) {
            String why = LogExport.describe(o.error());
            LOG.warn("Session Log: cannot " + (log == null ? "open " : "read again ") + file + ": " + why);
            if (log == null) {
                openError = o.error().getMessage() == null ? why : o.error().getMessage();
            } else {
                reopenError = why;
            }
            showStatus();
            return;
        }
        Replayer old = replayer;
        SharedLog oldShared = shared;
        Replayer r = o.replayer();
        boolean play = old != null && carryOn(old, r);
        r.addListener(new Listener(r));
        SharedLog s = o.shared();
        SessionLog l = s.log();
        shared = s;
        log = l;
        replayer = r;
        openError = null;
        reopenError = null;
        playFailure = null;
        if (play) {
            r.play();
        }
        transport.setEnabled(true);
        timeline.setRange(l.startNanos(), l.endNanos());
        timeline.setStops(l.problems().stream().map(LogProblem::timeNanos).toList());
        HoldMarks holds = holdMarks(l);
        timeline.setHolds(holds);
        inspector.setHolds(holds);
        timeline.setSnapshot(null);
        if (densityJob != null) {
            densityJob.cancel(); // the old pass ends soon and lets go of the old log
        }
        startDensity(s);
        inspector.setLog(s, r.position());
        retire(old, oldShared);
        if (l.complete()) {
            growing = false; // the spy closed it while we looked
        }
        showStatus();
        showReplayState();
    }

    /**
     * The new replayer takes over from the old: same speed, just past the same message. Says whether
     * the old one was playing (the new one plays once it is in place).
     */
    private boolean carryOn(Replayer old, Replayer r) {
        boolean playing = old.playing();
        old.pause(); // nothing more from the old log: what it published last is final
        r.setSpeed(old.speed());
        LogMessage last = old.lastPublished();
        try {
            if (last != null) {
                r.seekAfter(last); // the same file: the reopened log has the same message at the same place
                lastPublished = last;
                return playing;
            }
        } catch (RuntimeException e) {
            LOG.warn("Session Log: " + file + " read again lacks the message last shown; going on at its time: " + e);
        }
        r.seek(old.position());
        return playing;
    }

    /**
     * Stops a replaced replayer and lets its log go, off the UI thread: stopping waits for the play
     * thread, and the log closes when its last reader (timeline pass, inspector, plot) is done.
     */
    private static void retire(Replayer r, SharedLog s) {
        if (r == null && s == null) {
            return;
        }
        Job j = Job.create("Closing a replaced Session Log", (IProgressMonitor monitor) -> {
            if (r != null) {
                r.close();
            }
            if (s != null) {
                s.retire();
            }
            return Status.OK_STATUS;
        });
        j.setSystem(true);
        j.schedule();
    }

    /** Tells the editor what its replayer does; a replaced replayer's late news is ignored. */
    private final class Listener implements ReplayListener {
        private final Replayer r;

        Listener(Replayer r) {
            this.r = r;
        }

        @Override
        public void moved(long timeNanos, LogMessage last) {
            if (r == replayer) {
                lastPublished = last;
                updates.request();
            }
        }

        @Override
        public void stateChanged(boolean playing, double speed) {
            if (r != replayer) {
                return;
            }
            Exception failure = playing ? null : r.failure();
            String before = playFailure;
            if (failure != null) {
                playFailure = LogExport.describe(failure);
            } else if (playing) {
                playFailure = null; // played again: the failure is history
            }
            if (!java.util.Objects.equals(before, playFailure)) {
                statusUpdates.request();
            }
            updates.request();
        }
    }

    private void startDensity(SharedLog s) {
        SessionLog l = s.log();
        TimelineDensity d = new TimelineDensity(l.startNanos(), l.endNanos(), BUCKETS, columns);
        density = d;
        densityJob = Job.create("Reading the streams of " + file.getFileName(), (IProgressMonitor monitor) -> {
            if (!s.acquire()) {
                return Status.CANCEL_STATUS; // replaced and closed before the pass began
            }
            long started = System.nanoTime();
            monitor.beginTask("Reading " + file.getFileName(), 1000);
            int[] done = { 0 };
            try {
                d.fill(l, f -> {
                    int now = (int) (f * 1000);
                    monitor.worked(now - done[0]);
                    done[0] = now;
                    densityUpdates.request();
                }, monitor::isCanceled);
            } catch (IOException | RuntimeException e) {
                LOG.warn("Session Log: timeline of " + file + " stopped: " + e.getMessage());
            } finally {
                s.release();
            }
            pace.timelinePassed(System.nanoTime() - started);
            densityUpdates.request();
            monitor.done();
            return Status.OK_STATUS;
        });
        densityJob.setSystem(false);
        densityJob.schedule();
    }

    private void showDensity() {
        TimelineDensity d = density;
        if (d != null && timeline != null && !timeline.canvas().isDisposed()) {
            timeline.setSnapshot(d.snapshot());
        }
    }

    private void showStatus() {
        if (status.isDisposed()) {
            return;
        }
        status.setText(statusText());
        // a log still being written lacks its summary by nature: that alone is no reason for alarm
        boolean alarming = openError != null || reopenError != null || playFailure != null || (log != null && !log.problems().isEmpty() && !(growing && log.problems().size() == 1));
        status.setForeground(status.getDisplay().getSystemColor(alarming ? SWT.COLOR_DARK_RED : SWT.COLOR_WIDGET_FOREGROUND));
        status.getParent().layout();
    }

    /**
     * What the status line says: the log, whether it is being read (again), where a damaged one
     * stopped, and what stopped play.
     */
    public String statusText() {
        SessionLog l = log;
        if (l == null) {
            return openError == null ? "Reading " + file + "\u2026" : "Cannot open " + file + ": " + openError;
        }
        StringBuilder s = new StringBuilder();
        s.append(switch (l.format()) {
            case SPY_LOG -> "Spy log";
            case PLAYER_TRACE -> "Recorded trace";
            case WRITELOG -> "Player writelog";
        });
        s.append(String.format(Locale.ROOT, ", %.3f s, %,d messages, %d connection%s", (l.endNanos() - l.startNanos()) / 1e9, l.messageCount(),
                l.connections().size(), l.connections().size() == 1 ? "" : "s"));
        try {
            s.append(String.format(Locale.ROOT, ", %,d bytes", Files.size(file)));
        } catch (IOException e) {
            // the size is only for information
        }
        if (growing) {
            s.append(" — still being written: read again as it grows");
        }
        if (openJob != null) {
            s.append(" — reading\u2026");
        }
        if (reopenError != null) {
            s.append("\nCannot read it again: ").append(reopenError);
        }
        String failure = playFailure;
        if (failure != null) {
            s.append("\nReplay stopped: ").append(failure);
        }
        List<LogProblem> problems = l.problems();
        for (LogProblem p : problems) {
            s.append("\n").append(p.where()).append(String.format(Locale.ROOT, " (%.3f s): ", (p.timeNanos() - l.startNanos()) / 1e9))
                    .append(p.text());
        }
        return s.toString();
    }

    private void showReplayState() {
        Replayer r = replayer;
        SessionLog l = log;
        if (r == null || l == null || timeline.canvas().isDisposed()) {
            return;
        }
        long p = r.position();
        transport.show((p - l.startNanos()) / 1e9, (l.endNanos() - l.startNanos()) / 1e9, r.playing(), r.speed());
        timeline.setPosition(p);
        inspector.follow(p, lastPublished);
    }

    private void seek(long timeNanos) {
        Replayer r = replayer;
        if (r != null) {
            lastPublished = null;
            r.seek(timeNanos);
            updates.request();
        }
    }

    /** A row chosen in the inspector: the replay moves there and publishes it, so views show that moment. */
    private void inspectorSelected(LogMessage m) {
        Replayer r = replayer;
        if (r != null) {
            r.seekTo(m);
            lastPublished = r.stepForward();
            updates.request();
        }
    }

    // --- for the tests, the Plot view and the export actions -------------------------------------

    public Path file() {
        return file;
    }

    /** The log on show, or null while the file is first read or when it could not be opened at all. */
    public SessionLog log() {
        return log;
    }

    /** The log on show with its readers' hold on it: read it only between acquire and release. */
    public SharedLog sharedLog() {
        return shared;
    }

    /** Whether the file is being read (opened, or opened again) in the background. UI thread. */
    public boolean reading() {
        return openJob != null;
    }

    public Replayer replayer() {
        return replayer;
    }

    /** The bus this editor replays into. */
    public StreamBus bus() {
        return bus;
    }

    /** This editor's entry in {@link BusSources}. */
    public String sourceId() {
        return sourceId;
    }

    public MessageColumns columns() {
        return columns;
    }

    /** The log's robot holds (none if it has none or they cannot be read: the rest of the log still shows). */
    private HoldMarks holdMarks(SessionLog l) {
        try {
            return new HoldMarks(l.holdEntries(), l.endNanos());
        } catch (java.io.IOException | RuntimeException e) {
            LOG.warn("Session Log: robot holds of " + l.path() + " not shown: " + e.getMessage());
            return HoldMarks.none();
        }
    }

    public TimelineCanvas timeline() {
        return timeline;
    }

    public InspectorPanel inspector() {
        return inspector;
    }

    public TransportBar transport() {
        return transport;
    }

    /** Whether the background pass that fills the timeline has finished. */
    public boolean timelineComplete() {
        Job j = densityJob;
        return j != null && j.getState() == Job.NONE && j.getResult() != null;
    }

    /**
     * Reads the file again in the background, keeping the replay position (a growing log shows what was
     * added); returns at once, the log on show stays usable until the new reading replaces it.
     */
    public void reload() {
        startOpen(false);
    }

    /** Opens a new Robot View following this log's replay. */
    public RobotView showInRobotView() throws PartInitException {
        IWorkbenchPage page = getSite().getPage();
        // a fresh secondary id: views kept from an earlier session must not be taken over
        String secondary = "log-" + Long.toString(System.currentTimeMillis(), 36) + "-" + VIEWS.incrementAndGet();
        RobotView view = (RobotView) page.showView(RobotView.ID, secondary, IWorkbenchPage.VIEW_ACTIVATE);
        view.followSource(sourceId);
        return view;
    }

    /** Opens a Plot view on this log. */
    public PlotView showPlot() throws PartInitException {
        PlotView plot = (PlotView) getSite().getPage().showView(PlotView.ID, null, IWorkbenchPage.VIEW_ACTIVATE);
        plot.setEditor(this);
        return plot;
    }

    private final class Transport implements TransportBar.Host {
        @Override
        public void toStart() {
            SessionLog l = log;
            if (l != null) {
                seek(l.startNanos());
            }
        }

        @Override
        public void stepBack() {
            Replayer r = replayer;
            if (r != null) {
                lastPublished = r.stepBack();
                updates.request();
            }
        }

        @Override
        public void playPause() {
            Replayer r = replayer;
            if (r != null) {
                if (r.playing()) {
                    r.pause();
                } else {
                    r.play();
                }
                updates.request();
            }
        }

        @Override
        public void stepForward() {
            Replayer r = replayer;
            if (r != null) {
                lastPublished = r.stepForward();
                updates.request();
            }
        }

        @Override
        public void speed(double speed) {
            Replayer r = replayer;
            if (r != null) {
                r.setSpeed(speed);
            }
        }

        @Override
        public void seekSeconds(double seconds) {
            SessionLog l = log;
            if (l != null) {
                seek(l.startNanos() + Math.round(seconds * 1e9));
            }
        }

        @Override
        public void reload() {
            SessionLogEditor.this.reload();
        }

        @Override
        public void showInRobotView() {
            try {
                SessionLogEditor.this.showInRobotView();
            } catch (PartInitException e) {
                LOG.log(e.getStatus());
            }
        }

        @Override
        public void plot() {
            try {
                showPlot();
            } catch (PartInitException e) {
                LOG.log(e.getStatus());
            }
        }

        @Override
        public void export(Composite anchor) {
            ExportMenu.show(anchor, SessionLogEditor.this);
        }
    }

    @Override
    public void dispose() {
        // nothing here waits: jobs are cancelled and end by themselves, logs close when their readers are done
        disposed = true;
        openGeneration++;
        if (openJob != null) {
            openJob.cancel();
            openJob = null;
        }
        if (densityJob != null) {
            densityJob.cancel();
        }
        retire(replayer, shared);
        replayer = null;
        shared = null;
        log = null;
        reader.shutdown(); // reads queued still run, holding the log, and show nothing
        try {
            if (source != null) {
                source.close(); // views following this log go back to Live
            }
        } catch (Exception e) {
            LOG.log(new Status(IStatus.WARNING, "org.stagecraft.replay.ui", e.getMessage(), e));
        }
        if (processors != null) {
            processors.stopAll();
        }
        bus.close();
        super.dispose();
    }

    @Override
    public void setFocus() {
        timeline.canvas().setFocus(); // where the transport keys work
    }

    @Override
    public void doSave(IProgressMonitor monitor) {
        // a log is read, never written
    }

    @Override
    public void doSaveAs() {
    }

    @Override
    public boolean isDirty() {
        return false;
    }

    @Override
    public boolean isSaveAsAllowed() {
        return false;
    }
}
