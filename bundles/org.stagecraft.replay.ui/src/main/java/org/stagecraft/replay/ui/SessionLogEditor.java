package org.stagecraft.replay.ui;

import java.nio.file.Path;
import java.util.Objects;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.swt.SWT;
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
import org.eclipse.ui.contexts.IContextActivation;
import org.eclipse.ui.contexts.IContextService;
import org.eclipse.ui.part.EditorPart;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.core.streams.BusSources;
import org.stagecraft.replay.analysis.MessageColumns;
import org.stagecraft.replay.analysis.TimelineDensity;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.replay.session.FollowPace;
import org.stagecraft.replay.session.ReplaySession;
import org.stagecraft.replay.session.SessionView;
import org.stagecraft.replay.session.SharedLog;
import org.stagecraft.replay.ui.internal.EditorCommand;
import org.stagecraft.replay.ui.internal.EditorInputs;
import org.stagecraft.replay.ui.internal.InspectorPanel;
import org.stagecraft.replay.ui.internal.TimelineCanvas;
import org.stagecraft.replay.ui.internal.TransportBar;
import org.stagecraft.replay.ui.internal.UiThrottle;
import org.stagecraft.replay.ui.internal.WorkbenchThreads;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamProcessors;
import org.stagecraft.views.RobotView;

/**
 * The Session Log editor: shows a spy log, a recorded trace or a Player writelog file replayed by a
 * {@link ReplaySession} (opening, reading again, following a growing log, the timeline pass: all
 * there, without UI) into a stream bus of its own, registered as a {@link BusSources} entry so Robot
 * Views (and anything else on a bus) can follow it exactly as they follow live data. Shows a timeline
 * (a track per stream), the transport and the packet inspector; the Plot view and the export work on it.
 *
 * <p>This class holds the widgets and wires them to the session. The transport, Reload, Plot, Show in
 * Robot View and Export are commands ({@link EditorCommand}, contributed in plugin.xml with key
 * bindings a user can change): the buttons and the keys run the same. The replay thread and the
 * background work only ask for UI updates ({@link UiThrottle}); nothing on the UI thread waits for them.
 */
public class SessionLogEditor extends EditorPart {
    public static final String ID = "org.stagecraft.replay.ui.sessionLogEditor";
    /** Timeline resolution: buckets across the whole log, whatever its length. */
    public static final int BUCKETS = ReplaySession.BUCKETS;
    private static final ILog LOG = ILog.of(Platform.getBundle("org.stagecraft.replay.ui"));
    private static final AtomicInteger VIEWS = new AtomicInteger();

    private @Nullable Path file;
    private final MessageColumns columns = new MessageColumns(Contributions.workbench().codecs());
    private final StreamBus bus = new StreamBus();
    private final ExecutorService reader = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "Session Log inspector reader");
        t.setDaemon(true);
        return t;
    });
    private @Nullable StreamProcessors processors;
    private @Nullable AutoCloseable source;
    private @Nullable String sourceId;
    private @Nullable ReplaySession session;

    private @Nullable TransportBar transport;
    private @Nullable Label status;
    private @Nullable TimelineCanvas timeline;
    private @Nullable InspectorPanel inspector;
    private @Nullable UiThrottle updates, densityUpdates, statusUpdates;
    private @Nullable IContextActivation timelineKeys;

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
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

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createPartControl(Composite parent) {
        Display display = parent.getDisplay();
        // init() refused an input without a local file
        session = new ReplaySession(Objects.requireNonNull(file), columns, bus, new WorkbenchThreads(display),
                new FollowPace(ReplaySession.FOLLOW_MILLIS, ReplaySession.FOLLOW_FACTOR), new View());
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
        timeline = new TimelineCanvas(split, session.transport()::seek);
        inspector = new InspectorPanel(split, columns, reader, session::position, session.transport()::select);
        split.setWeights(35, 65);
        updates = new UiThrottle(display, 50, this::showReplayState);
        densityUpdates = new UiThrottle(display, 250, this::showDensity);
        statusUpdates = new UiThrottle(display, 100, this::showStatus);
        activateKeys();

        SharedWorld.of(bus); // the world model listens from the first message: geometry replies come once
        processors = Contributions.workbench().startProcessors(bus); // derived streams, as on the live bus
        registerSource();
        transport.setEnabled(false);
        session.open();
        display.timerExec(ReplaySession.FOLLOW_MILLIS, this::follow);
    }

    /**
     * The editor's key bindings (plugin.xml): its context while the editor is active, and the
     * timeline's while the timeline has the focus, so plain keys (Space, arrows) act only there and a
     * text field in the editor keeps them.
     */
    private void activateKeys() {
        IContextService contexts = getSite().getService(IContextService.class);
        contexts.activateContext(EditorCommand.EDITOR_CONTEXT); // the part's service withdraws it with the part
        timeline.canvas().addListener(SWT.FocusIn, e -> {
            if (timelineKeys == null) {
                timelineKeys = contexts.activateContext(EditorCommand.TIMELINE_CONTEXT);
            }
        });
        timeline.canvas().addListener(SWT.FocusOut, e -> {
            if (timelineKeys != null) {
                contexts.deactivateContext(timelineKeys);
                timelineKeys = null;
            }
        });
    }

    /** Looks at a log still being written while the session follows it ({@link ReplaySession#follow()}). */
    private void follow() {
        if (timeline.canvas().isDisposed()) {
            return;
        }
        long next = session.follow();
        if (next >= 0) {
            timeline.canvas().getDisplay().timerExec((int) Math.min(Integer.MAX_VALUE, next), this::follow);
        }
    }

    private void registerSource() {
        String id = "log:" + file.toAbsolutePath();
        for (int n = 2; BusSources.find(id).isPresent(); n++) {
            id = "log:" + file.toAbsolutePath() + "#" + n; // the same file open twice
        }
        sourceId = id;
        source = BusSources.add(new BusSources.Source(id, "Log " + file.getFileName(), bus));
    }

    /** What the session tells the editor: a new log to show, and updates to ask for. */
    private final class View implements SessionView {
        @Override
        public void logShown(SharedLog shared, Replayer replayer) {
            SessionLog l = shared.log();
            transport.setEnabled(true);
            timeline.setRange(l.startNanos(), l.endNanos());
            timeline.setStops(l.problems().stream().map(LogProblem::timeNanos).toList());
            timeline.setHolds(session.holds());
            inspector.setHolds(session.holds());
            timeline.setSnapshot(null);
            inspector.setLog(shared, replayer.position());
        }

        @Override
        public void statusChanged() {
            if (Display.getCurrent() != null) {
                showStatus();
            } else {
                statusUpdates.request();
            }
        }

        @Override
        public void replayMoved() {
            updates.request();
        }

        @Override
        public void timelineFilled() {
            densityUpdates.request();
        }

        @Override
        public void warning(String text) {
            LOG.warn("Session Log: " + text);
        }
    }

    private void showDensity() {
        TimelineDensity d = session.density();
        if (d != null && !timeline.canvas().isDisposed()) {
            timeline.setSnapshot(d.snapshot());
        }
    }

    private void showStatus() {
        if (status.isDisposed()) {
            return;
        }
        status.setText(session.statusText());
        status.setForeground(status.getDisplay().getSystemColor(session.alarming() ? SWT.COLOR_DARK_RED : SWT.COLOR_WIDGET_FOREGROUND));
        status.getParent().layout();
    }

    private void showReplayState() {
        Replayer r = session.replayer();
        SessionLog l = session.log();
        if (r == null || l == null || timeline.canvas().isDisposed()) {
            return;
        }
        long p = r.position();
        transport.show((p - l.startNanos()) / 1e9, (l.endNanos() - l.startNanos()) / 1e9, r.playing(), r.speed());
        timeline.setPosition(p);
        inspector.follow(p, session.transport().lastPublished());
    }

    /** The transport bar's controls: its buttons run the editor's commands. */
    private final class Transport implements TransportBar.Host {
        @Override
        public void run(EditorCommand command) {
            try {
                command.run(SessionLogEditor.this);
            } catch (PartInitException e) {
                LOG.log(e.getStatus());
            }
        }

        @Override
        public void speed(double speed) {
            session.transport().setSpeed(speed);
        }

        @Override
        public void seekSeconds(double seconds) {
            session.transport().seekSeconds(seconds);
        }
    }

    // --- the commands, and for the tests, the Plot view and the export ----------------------------

    /** The replay session this editor shows. */
    public @Nullable ReplaySession session() {
        return session;
    }

    public @Nullable Path file() {
        return file;
    }

    /** The log on show, or null while the file is first read or when it could not be opened at all. */
    public @Nullable SessionLog log() {
        return session.log();
    }

    /** The log on show with its readers' hold on it: read it only between acquire and release. */
    public @Nullable SharedLog sharedLog() {
        return session.sharedLog();
    }

    /** Whether the file is being read (opened, or opened again) in the background. UI thread. */
    public boolean reading() {
        return session.reading();
    }

    /** Whether the editor is following a log that is still being written. */
    public boolean following() {
        return session.following();
    }

    /** What the status line says ({@link ReplaySession#statusText()}). */
    public String statusText() {
        return session.statusText();
    }

    public @Nullable Replayer replayer() {
        return session.replayer();
    }

    /** The bus this editor replays into. */
    public StreamBus bus() {
        return bus;
    }

    /** This editor's entry in {@link BusSources}. */
    public @Nullable String sourceId() {
        return sourceId;
    }

    public MessageColumns columns() {
        return columns;
    }

    public @Nullable TimelineCanvas timeline() {
        return timeline;
    }

    public @Nullable InspectorPanel inspector() {
        return inspector;
    }

    public @Nullable TransportBar transport() {
        return transport;
    }

    /** Whether the background pass that fills the timeline has finished. */
    public boolean timelineComplete() {
        return session.timelineComplete();
    }

    /**
     * Reads the file again in the background, keeping the replay position (a growing log shows what was
     * added); returns at once, the log on show stays usable until the new reading replaces it.
     */
    public void reload() {
        session.reload();
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

    @Override
    public void dispose() {
        // nothing here waits: work is cancelled and ends by itself, logs close when their readers are done
        if (session != null) {
            session.close();
        }
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

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
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
