package org.stagecraft.replay.ui.internal;

import java.util.List;
import java.util.Locale;
import java.util.function.LongConsumer;

import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.stagecraft.replay.log.HoldMarks;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.stagecraft.replay.analysis.TimelineDensity;

/**
 * The Session Log's timeline, drawn with GC: a time axis, a row of marks (red: decode problems and
 * unframed bytes, orange: gaps, a red triangle where the readable log stops; lavender: robots held, with
 * violet ticks for injected zero commands and held-back messages), and one track per stream
 * whose bars are its message density per bucket (scaled to the track's busiest bucket), with the replay
 * cursor across all. Clicking or dragging seeks. Shows a {@link TimelineDensity.Snapshot}; holds nothing
 * else of the log.
 */
public final class TimelineCanvas {
    public static final int LABEL_WIDTH = 240, AXIS = 18, MARKS = 10, ROW = 14;

    private final Canvas canvas;
    private final LongConsumer onSeek;
    private TimelineDensity.@Nullable Snapshot snapshot;
    private long start, end = 1;
    private long position = Long.MIN_VALUE;
    private List<Long> stops = List.of();
    private HoldMarks holds = HoldMarks.none();
    private boolean dragging;

    public TimelineCanvas(Composite parent, LongConsumer onSeek) {
        this.onSeek = onSeek;
        // its own scroll bar, not a ScrolledComposite: the axis and marks stay put while the tracks scroll
        canvas = new Canvas(parent, SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND | SWT.V_SCROLL | SWT.BORDER);
        canvas.addListener(SWT.Resize, e -> layout());
        canvas.getVerticalBar().addListener(SWT.Selection, e -> canvas.redraw());
        canvas.addListener(SWT.MouseVerticalWheel, e -> {
            var bar = canvas.getVerticalBar();
            bar.setSelection(Math.max(0, Math.min(bar.getMaximum() - bar.getThumb(), bar.getSelection() - e.count * ROW)));
            canvas.redraw();
        });
        canvas.addListener(SWT.Paint, e -> paint(e.gc));
        canvas.addListener(SWT.MouseDown, e -> {
            if (e.button == 1 && e.x >= LABEL_WIDTH) {
                dragging = true;
                seekTo(e);
            }
        });
        canvas.addListener(SWT.MouseMove, e -> {
            if (dragging) {
                seekTo(e);
            }
        });
        canvas.addListener(SWT.MouseUp, e -> dragging = false);
    }

    public Canvas control() {
        return canvas;
    }

    public Canvas canvas() {
        return canvas;
    }

    /** The log's time range (before any density is known). */
    public void setRange(long startNanos, long endNanos) {
        start = startNanos;
        end = Math.max(endNanos, startNanos + 1);
        canvas.redraw();
    }

    public void setSnapshot(TimelineDensity.@Nullable Snapshot s) {
        snapshot = s;
        if (s != null) {
            setRange(s.startNanos(), s.endNanos());
        }
        layout();
        canvas.redraw();
    }

    public TimelineDensity.@Nullable Snapshot snapshot() {
        return snapshot;
    }

    /** Where the log stops being readable (truncated or corrupt files). */
    public void setStops(List<Long> times) {
        stops = List.copyOf(times);
        canvas.redraw();
    }

    /** The robot holds of the log: held spans and injected/held-back instants, in the hold colour. */
    public void setHolds(HoldMarks marks) {
        holds = marks == null ? HoldMarks.none() : marks;
        canvas.redraw();
    }

    public HoldMarks holds() {
        return holds;
    }

    public void setPosition(long t) {
        if (t != position) {
            position = t;
            canvas.redraw();
        }
    }

    public long position() {
        return position;
    }

    /** Track labels in display order. */
    public List<String> trackLabels() {
        return snapshot == null ? List.of() : snapshot.tracks().stream().map(TimelineDensity.Track::label).toList();
    }

    /** Log time under window x (clamped to the log). */
    public long timeAt(int x) {
        int w = Math.max(1, canvas.getClientArea().width - LABEL_WIDTH - 4);
        double f = Math.max(0, Math.min(1, (x - LABEL_WIDTH) / (double) w));
        return start + Math.round(f * (end - start));
    }

    /** Window x of log time {@code t}. */
    public int xOf(long t) {
        int w = Math.max(1, canvas.getClientArea().width - LABEL_WIDTH - 4);
        return LABEL_WIDTH + (int) Math.round((double) (t - start) / (end - start) * w);
    }

    private void seekTo(Event e) {
        onSeek.accept(timeAt(e.x));
    }

    private void layout() {
        int rows = snapshot == null ? 0 : snapshot.tracks().size();
        int visible = Math.max(1, canvas.getClientArea().height - AXIS - MARKS);
        var bar = canvas.getVerticalBar();
        bar.setMaximum(Math.max(rows * ROW + 4, 1));
        bar.setThumb(Math.min(visible, bar.getMaximum()));
        bar.setPageIncrement(visible);
        bar.setIncrement(ROW);
        bar.setVisible(rows * ROW + 4 > visible);
    }

    private void paint(GC gc) {
        Rectangle area = canvas.getClientArea();
        var display = canvas.getDisplay();
        gc.setBackground(display.getSystemColor(SWT.COLOR_WHITE));
        gc.fillRectangle(area);
        gc.setAntialias(SWT.OFF);
        int right = area.width - 4;
        drawAxis(gc, right);
        drawMarks(gc);
        if (snapshot != null) {
            drawTracks(gc, right);
        } else {
            gc.setForeground(display.getSystemColor(SWT.COLOR_DARK_GRAY));
            gc.drawString("reading the log's streams\u2026", LABEL_WIDTH + 4, AXIS + MARKS + 2, true);
        }
        if (position != Long.MIN_VALUE) {
            int x = xOf(position);
            gc.setForeground(display.getSystemColor(SWT.COLOR_RED));
            gc.setLineWidth(2);
            gc.drawLine(x, 0, x, area.height);
            gc.setLineWidth(1);
        }
    }

    private void drawAxis(GC gc, int right) {
        var display = canvas.getDisplay();
        gc.setForeground(display.getSystemColor(SWT.COLOR_DARK_GRAY));
        gc.drawLine(LABEL_WIDTH, AXIS - 1, right, AXIS - 1);
        double seconds = (end - start) / 1e9;
        double step = niceStep(seconds / Math.max(1, (right - LABEL_WIDTH) / 80.0));
        for (double s = 0; s <= seconds + 1e-9; s += step) {
            int x = xOf(start + Math.round(s * 1e9));
            gc.drawLine(x, AXIS - 5, x, AXIS - 1);
            String label = step >= 1 ? String.format(Locale.ROOT, "%.0f s", s) : String.format(Locale.ROOT, "%.1f s", s);
            gc.drawString(label, x + 2, 0, true);
        }
        if (snapshot != null) {
            gc.drawString(snapshot.tracks().size() + " streams, " + snapshot.messages() + " entries", 4, 0, true);
        }
    }

    /** 1, 2 or 5 times a power of ten, at least {@code raw}. */
    static double niceStep(double raw) {
        if (!(raw > 0)) {
            return 1;
        }
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        for (double m : new double[] { 1, 2, 5, 10 }) {
            if (m * p >= raw) {
                return m * p;
            }
        }
        return 10 * p;
    }

    /**
     * Lavender band while held (under the other marks), its lower half ice blue while the simulated world stood
     * still, a violet tick per injected zero command, a lighter one per
     * held-back message, a red one the whole height of the row where a robot data breakpoint stopped.
     */
    static final int[] HOLD_BAND = { 226, 214, 248 }, INJECTED = { 120, 40, 200 }, HELD_BACK = { 170, 130, 230 },
            BREAK = { 210, 30, 30 }, FROZEN = { 150, 200, 235 };

    private void drawHolds(GC gc, int y) {
        if (holds.isEmpty()) {
            return;
        }
        gc.setBackground(new Color(HOLD_BAND[0], HOLD_BAND[1], HOLD_BAND[2]));
        for (HoldMarks.Span sp : holds.spans()) {
            int x0 = xOf(sp.startNanos()), x1 = Math.max(x0 + 1, xOf(sp.endNanos()));
            gc.fillRectangle(x0, y, x1 - x0, MARKS);
        }
        gc.setBackground(new Color(FROZEN[0], FROZEN[1], FROZEN[2]));
        for (HoldMarks.Span sp : holds.frozenSpans()) {
            int x0 = xOf(sp.startNanos()), x1 = Math.max(x0 + 1, xOf(sp.endNanos()));
            gc.fillRectangle(x0, y + MARKS / 2, x1 - x0, MARKS - MARKS / 2);
        }
        gc.setForeground(new Color(HELD_BACK[0], HELD_BACK[1], HELD_BACK[2]));
        for (long t : holds.heldBackTimes()) {
            gc.drawLine(xOf(t), y + MARKS / 2, xOf(t), y + MARKS - 1);
        }
        gc.setForeground(new Color(INJECTED[0], INJECTED[1], INJECTED[2]));
        for (long t : holds.injectedTimes()) {
            gc.drawLine(xOf(t), y, xOf(t), y + MARKS / 2);
        }
        gc.setForeground(new Color(BREAK[0], BREAK[1], BREAK[2]));
        for (long t : holds.breakTimes()) {
            gc.drawLine(xOf(t), y, xOf(t), y + MARKS - 1);
        }
    }

    private void drawMarks(GC gc) {
        var display = canvas.getDisplay();
        int y = AXIS;
        drawHolds(gc, y);
        if (snapshot != null) {
            Color gap = new Color(255, 140, 0);
            for (int b = 0; b < snapshot.buckets(); b++) {
                int x0 = xOf(bucketStart(b)), x1 = Math.max(x0 + 1, xOf(bucketStart(b + 1)));
                if (snapshot.problems()[b] > 0) {
                    gc.setBackground(display.getSystemColor(SWT.COLOR_RED));
                    gc.fillRectangle(x0, y, x1 - x0, MARKS / 2);
                }
                if (snapshot.gaps()[b] > 0) {
                    gc.setBackground(gap);
                    gc.fillRectangle(x0, y + MARKS / 2, x1 - x0, MARKS / 2);
                }
            }
        }
        gc.setBackground(display.getSystemColor(SWT.COLOR_RED));
        for (long t : stops) {
            int x = xOf(t);
            gc.fillPolygon(new int[] { x - 5, y, x + 5, y, x, y + MARKS });
        }
    }

    private long bucketStart(int b) {
        return start + (long) ((double) (end - start) * b / snapshot.buckets());
    }

    private void drawTracks(GC gc, int right) {
        var display = canvas.getDisplay();
        Color bar = new Color(48, 96, 192), stripe = new Color(244, 246, 250);
        int top = AXIS + MARKS;
        int y = top - canvas.getVerticalBar().getSelection();
        int bottom = canvas.getClientArea().height;
        int i = 0;
        for (TimelineDensity.Track t : snapshot.tracks()) {
            if (y + ROW <= top || y >= bottom) {
                y += ROW;
                i++;
                continue;
            }
            gc.setClipping(0, top, right + 4, bottom - top);
            if (i++ % 2 == 1) {
                gc.setBackground(stripe);
                gc.fillRectangle(0, y, right, ROW);
            }
            gc.setForeground(display.getSystemColor(SWT.COLOR_BLACK));
            gc.setClipping(new Rectangle(0, y, LABEL_WIDTH - 4, ROW).intersection(new Rectangle(0, top, right, bottom - top)));
            gc.drawString(t.label(), 4, y, true);
            gc.setClipping(0, top, right + 4, bottom - top);
            int max = t.max();
            gc.setBackground(bar);
            for (int b = 0; b < t.counts().length; b++) {
                int c = t.counts()[b];
                if (c == 0) {
                    continue;
                }
                int x0 = xOf(bucketStart(b)), x1 = Math.max(x0 + 1, xOf(bucketStart(b + 1)));
                // square root: a stream at a tenth of its peak rate is still clearly visible
                int h = Math.max(1, (int) Math.round(Math.sqrt((double) c / max) * (ROW - 3)));
                gc.fillRectangle(x0, y + ROW - 1 - h, x1 - x0, h);
            }
            y += ROW;
        }
        gc.setClipping((Rectangle) null);
    }
}
