package org.stagecraft.replay.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Platform;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.action.Action;
import org.eclipse.jface.action.IMenuManager;
import org.eclipse.jface.action.Separator;
import org.eclipse.jface.dialogs.IInputValidator;
import org.eclipse.jface.dialogs.InputDialog;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IMemento;
import org.eclipse.ui.IPartListener2;
import org.eclipse.ui.IViewSite;
import org.eclipse.ui.IWorkbenchPartReference;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.part.ViewPart;
import org.stagecraft.replay.analysis.RecordedSeries;
import org.stagecraft.replay.analysis.Series;
import org.stagecraft.replay.analysis.SeriesSampler;
import org.stagecraft.replay.analysis.SeriesSpec;
import org.stagecraft.replay.analysis.SeriesText;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.replay.ui.internal.PlotCanvas;
import org.stagecraft.replay.session.SharedLog;

/**
 * Plots numeric fields of a Session Log over time: several series, each a stream and a field path
 * ({@code position2d.pos.px}, {@code ranger:1 min(ranges)}), with the replay cursor as a vertical line;
 * a click moves the replay. Follows the Session Log editor last activated (or the one that opened it).
 * Series are sampled in the background over the log with a bounded number of points (about one per two
 * pixels, min-max thinned, {@link SeriesSampler}); derived streams, which no log holds, are recorded
 * from the editor's bus as the replay publishes them ({@link RecordedSeries}) and drawn with the rest.
 * The series texts persist in the view's memento.
 */
public class PlotView extends ViewPart {
    public static final String ID = "org.stagecraft.replay.ui.plot";
    private static final ILog LOG = ILog.of(Platform.getBundle("org.stagecraft.replay.ui"));
    private static final String SERIES = "series";
    /** How often the cursor follows the replay. */
    static final int CURSOR_MILLIS = 50;

    private final List<String> texts = new ArrayList<>();
    private final ExecutorService sampler = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "Plot sampler");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong generation = new AtomicLong();
    private @Nullable PlotCanvas plot;
    private @Nullable SessionLogEditor editor;
    private @Nullable SessionLog sampledLog;
    private int sampledWidth;
    private boolean sampling;
    private @Nullable IPartListener2 partListener;
    /** The last log sampling, per series, and the time range it covers. */
    private List<Series> sampled = List.of();
    private long sampledFrom, sampledTo = 1;
    /** Per series, what the editor's bus carried of derived streams; rebuilt with the series or the editor. */
    private final List<RecordedSeries> recorders = new ArrayList<>();
    private long drawnVersion = -1;

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void init(IViewSite site, IMemento memento) throws PartInitException {
        super.init(site, memento);
        if (memento != null) {
            for (IMemento s : memento.getChildren(SERIES)) {
                String text = s.getTextData();
                if (text != null && !text.isBlank()) {
                    texts.add(text.strip());
                }
            }
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createPartControl(Composite parent) {
        plot = new PlotCanvas(parent, this::seek);
        plot.control().addListener(org.eclipse.swt.SWT.Resize, e -> resample());
        IMenuManager menu = getViewSite().getActionBars().getMenuManager();
        menu.setRemoveAllWhenShown(true);
        menu.addMenuListener(this::fillMenu);
        menu.add(new Separator());
        getViewSite().getActionBars().getToolBarManager().add(new Action("Add series\u2026") {
            @Override
            public void run() {
                askForSeries();
            }
        });
        partListener = new IPartListener2() {
            @Override
            public void partActivated(IWorkbenchPartReference ref) {
                if (ref.getPart(false) instanceof SessionLogEditor e) {
                    setEditor(e);
                }
            }

            @Override
            public void partClosed(IWorkbenchPartReference ref) {
                if (ref.getPart(false) == editor) {
                    setEditor(null);
                }
            }
        };
        getSite().getPage().addPartListener(partListener);
        IEditorPart active = getSite().getPage().getActiveEditor();
        if (active instanceof SessionLogEditor e) {
            setEditor(e);
        }
        parent.getDisplay().timerExec(CURSOR_MILLIS, this::tick);
    }

    private void fillMenu(IMenuManager m) {
        m.add(new Action("Add series\u2026") {
            @Override
            public void run() {
                askForSeries();
            }
        });
        for (String t : List.copyOf(texts)) {
            m.add(new Action("Remove " + t) {
                @Override
                public void run() {
                    removeSeries(t);
                }
            });
        }
    }

    private void askForSeries() {
        IInputValidator valid = text -> {
            try {
                SeriesText.spec(text, editorColumnsRegistry());
                return null;
            } catch (IllegalArgumentException e) {
                return e.getMessage();
            }
        };
        InputDialog d = new InputDialog(plot.control().getShell(), "Add series",
                "Stream and numeric field, e.g. position2d.pos.px, ranger:1 min(ranges), laser mean(ranges),\n"
                        + "or a stream pattern and a field: type=1 dev=4 index=0 | vel.px",
                "position2d.pos.px", valid);
        if (d.open() == Window.OK) {
            addSeries(d.getValue());
        }
    }

    private org.stagecraft.player.codec.CodecRegistry editorColumnsRegistry() {
        return editor != null ? editor.columns().registry() : org.stagecraft.core.extensions.Contributions.workbench().codecs();
    }

    /** Adds a series by its text ({@link SeriesText}). @throws IllegalArgumentException when it does not parse */
    public void addSeries(String text) {
        SeriesText.spec(text, editorColumnsRegistry());
        texts.add(text.strip());
        record();
        resample(true);
    }

    public void removeSeries(String text) {
        texts.remove(text);
        record();
        resample(true);
    }

    public List<String> seriesTexts() {
        return List.copyOf(texts);
    }

    /** What is drawn now. */
    public List<Series> series() {
        return plot.series();
    }

    public @Nullable PlotCanvas canvas() {
        return plot;
    }

    public @Nullable SessionLogEditor editor() {
        return editor;
    }

    /** Plots this editor's log (null: none). */
    public void setEditor(@Nullable SessionLogEditor e) {
        if (e == editor) {
            return;
        }
        editor = e;
        setContentDescription(e == null ? "No Session Log" : e.getPartName());
        record();
        resample(true);
    }

    /** Records every series' derived streams from the editor's bus (the replay's). */
    private void record() {
        recorders.forEach(RecordedSeries::close);
        recorders.clear();
        SessionLogEditor e = editor;
        if (e == null) {
            return;
        }
        for (String t : texts) {
            try {
                recorders.add(new RecordedSeries(SeriesText.spec(t, e.columns().registry()), e.bus(),
                        RecordedSeries.DEFAULT_CAPACITY));
            } catch (IllegalArgumentException ex) {
                LOG.warn("Plot: series '" + t + "': " + ex.getMessage());
            }
        }
        drawnVersion = -1;
    }

    private long recordedVersion() {
        long v = 0;
        for (RecordedSeries r : recorders) {
            v += r.version();
        }
        return v;
    }

    /** The log's samples with what was recorded from the bus, series by series. */
    private void draw() {
        List<Series> out = new ArrayList<>();
        for (int i = 0; i < sampled.size(); i++) {
            Series s = sampled.get(i);
            out.add(i < recorders.size() ? s.merge(recorders.get(i).snapshot(sampledFrom, sampledTo)) : s);
        }
        drawnVersion = recordedVersion();
        plot.setData(out, sampledFrom, sampledTo, sampledFrom);
    }

    private void seek(long t) {
        SessionLogEditor e = editor;
        Replayer r = e == null ? null : e.replayer();
        if (r != null) {
            r.seek(t);
        }
    }

    /** Follows the replay cursor; notices a reloaded log. */
    private void tick() {
        if (plot == null || plot.control().isDisposed()) {
            return;
        }
        SessionLogEditor e = editor;
        Replayer r = e == null ? null : e.replayer();
        if (r != null) {
            plot.setCursor(r.position());
        }
        if (e != null && e.log() != sampledLog) {
            resample(true);
        } else if (!sampling && recordedVersion() != drawnVersion) {
            draw();
        }
        plot.control().getDisplay().timerExec(CURSOR_MILLIS, this::tick);
    }

    private void resample() {
        resample(false);
    }

    private void resample(boolean always) {
        if (plot == null || plot.control().isDisposed()) {
            return;
        }
        int width = plot.plotWidth();
        SessionLogEditor e = editor;
        SharedLog shared = e == null ? null : e.sharedLog();
        SessionLog log = shared == null ? null : shared.log();
        if (!always && log == sampledLog && Math.abs(width - sampledWidth) < 16) {
            return;
        }
        sampledLog = log;
        sampledWidth = width;
        if (log == null) {
            sampled = List.of();
            plot.setData(List.of(), 0, 1, 0);
            plot.setMessage(e == null ? "Open a Session Log to plot it" : "The log could not be opened");
            return;
        }
        List<SeriesSpec> specs = new ArrayList<>();
        for (String t : texts) {
            try {
                specs.add(SeriesText.spec(t, e.columns().registry()));
            } catch (IllegalArgumentException ex) {
                LOG.warn("Plot: series '" + t + "': " + ex.getMessage());
            }
        }
        long g = generation.incrementAndGet();
        sampling = true;
        int buckets = Math.max(16, width / 2);
        long from = log.startNanos(), to = log.endNanos();
        var display = plot.control().getDisplay();
        sampler.execute(() -> {
            // holding the log: a reload replacing it meanwhile closes it only after this pass
            if (!shared.acquire()) {
                return; // already replaced and closed: tick() samples the new one
            }
            List<Series> out;
            String problem = null;
            try {
                out = SeriesSampler.sample(log, specs, from, to, buckets, () -> generation.get() != g);
            } catch (Exception ex) {
                out = List.of();
                problem = "Cannot read the log: " + ex.getMessage();
            } finally {
                shared.release();
            }
            List<Series> result = out;
            String message = problem;
            if (!display.isDisposed()) {
                display.asyncExec(() -> {
                    if (g == generation.get() && !plot.control().isDisposed()) {
                        sampling = false;
                        sampled = result;
                        sampledFrom = from;
                        sampledTo = to;
                        draw();
                        if (message != null) {
                            plot.setMessage(message);
                        }
                    }
                });
            }
        });
    }

    /** Whether a sampling pass is under way (tests wait for it to end). */
    public boolean sampling() {
        return sampling;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void saveState(IMemento memento) {
        for (String t : texts) {
            memento.createChild(SERIES).putTextData(t);
        }
    }

    @Override
    public void setFocus() {
        plot.control().setFocus();
    }

    @Override
    public void dispose() {
        if (partListener != null) {
            getSite().getPage().removePartListener(partListener);
        }
        generation.incrementAndGet();
        sampler.shutdownNow();
        recorders.forEach(RecordedSeries::close);
        super.dispose();
    }
}
