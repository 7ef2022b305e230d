package org.stagecraft.replay.ui.internal;

import java.util.List;
import java.util.Locale;
import java.util.function.LongConsumer;

import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Composite;
import org.stagecraft.replay.analysis.Series;

/**
 * Draws sampled series over a time range with GC: axes with round ticks, one colour per series and a
 * legend, and the replay cursor as a vertical line. Clicking seeks. Shows what it is given; sampling is
 * the view's job.
 */
public final class PlotCanvas {
    static final int LEFT = 64, RIGHT = 12, TOP = 8, BOTTOM = 22;
    /** Series colours, in order. */
    public static final int[] PALETTE = { 0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf };

    private final Canvas canvas;
    private List<Series> series = List.of();
    private long from, to = 1, origin;
    private long cursor = Long.MIN_VALUE;
    private String message = "Add a series: e.g. position2d.pos.px or ranger:1 min(ranges)";

    public PlotCanvas(Composite parent, LongConsumer onSeek) {
        canvas = new Canvas(parent, SWT.DOUBLE_BUFFERED | SWT.NO_BACKGROUND);
        canvas.addListener(SWT.Paint, e -> paint(e.gc));
        canvas.addListener(SWT.MouseDown, e -> {
            if (e.button == 1 && e.x >= LEFT) {
                onSeek.accept(timeAt(e.x));
            }
        });
    }

    public Canvas control() {
        return canvas;
    }

    /** New data over {@code [fromNanos, toNanos]}; times are labelled in seconds after {@code originNanos}. */
    public void setData(List<Series> data, long fromNanos, long toNanos, long originNanos) {
        series = List.copyOf(data);
        from = fromNanos;
        to = Math.max(toNanos, fromNanos + 1);
        origin = originNanos;
        canvas.redraw();
    }

    public List<Series> series() {
        return series;
    }

    /** A line shown instead of the plot (nothing to show, or why not). */
    public void setMessage(String text) {
        message = text;
        canvas.redraw();
    }

    public void setCursor(long t) {
        if (t != cursor) {
            cursor = t;
            canvas.redraw();
        }
    }

    public long cursor() {
        return cursor;
    }

    /** The width the data can use, in pixels (the view samples about one bucket per two pixels). */
    public int plotWidth() {
        return Math.max(1, canvas.getClientArea().width - LEFT - RIGHT);
    }

    public long timeAt(int x) {
        double f = Math.max(0, Math.min(1, (x - LEFT) / (double) plotWidth()));
        return from + Math.round(f * (to - from));
    }

    private int xOf(long t) {
        return LEFT + (int) Math.round((double) (t - from) / (to - from) * plotWidth());
    }

    private void paint(GC gc) {
        Rectangle area = canvas.getClientArea();
        var display = canvas.getDisplay();
        gc.setBackground(display.getSystemColor(SWT.COLOR_WHITE));
        gc.fillRectangle(area);
        int h = Math.max(1, area.height - TOP - BOTTOM);
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (Series s : series) {
            double[] r = s.range();
            if (!Double.isNaN(r[0])) {
                lo = Math.min(lo, r[0]);
                hi = Math.max(hi, r[1]);
            }
        }
        gc.setForeground(display.getSystemColor(SWT.COLOR_DARK_GRAY));
        gc.drawRectangle(LEFT, TOP, plotWidth(), h);
        if (lo > hi) {
            gc.drawString(message, LEFT + 8, TOP + 8, true);
            drawCursor(gc, h);
            return;
        }
        if (hi - lo < 1e-12) {
            lo -= 1;
            hi += 1;
        }
        double pad = (hi - lo) * 0.05;
        lo -= pad;
        hi += pad;
        drawTicks(gc, lo, hi, h);
        gc.setAntialias(SWT.ON);
        gc.setLineWidth(1);
        int legendY = TOP + 4;
        for (int i = 0; i < series.size(); i++) {
            Series s = series.get(i);
            int rgb = PALETTE[i % PALETTE.length];
            Color c = new Color((rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff);
            gc.setForeground(c);
            int[] points = new int[s.size() * 2];
            for (int p = 0; p < s.size(); p++) {
                points[2 * p] = xOf(s.times()[p]);
                points[2 * p + 1] = TOP + (int) Math.round((hi - s.values()[p]) / (hi - lo) * h);
            }
            if (s.size() == 1) {
                gc.drawOval(points[0] - 2, points[1] - 2, 4, 4);
            } else {
                gc.drawPolyline(points);
            }
            String label = s.spec().label() + (s.size() == 0 ? " (no data)" : "");
            gc.drawLine(LEFT + 8, legendY + 7, LEFT + 24, legendY + 7);
            gc.drawString(label, LEFT + 28, legendY, true);
            legendY += gc.getFontMetrics().getHeight();
        }
        gc.setAntialias(SWT.OFF);
        drawCursor(gc, h);
    }

    private void drawCursor(GC gc, int h) {
        if (cursor != Long.MIN_VALUE && cursor >= from && cursor <= to) {
            int x = xOf(cursor);
            gc.setForeground(canvas.getDisplay().getSystemColor(SWT.COLOR_RED));
            gc.setLineWidth(2);
            gc.drawLine(x, TOP, x, TOP + h);
            gc.setLineWidth(1);
        }
    }

    private void drawTicks(GC gc, double lo, double hi, int h) {
        gc.setForeground(canvas.getDisplay().getSystemColor(SWT.COLOR_DARK_GRAY));
        double step = TimelineCanvas.niceStep((hi - lo) / Math.max(2, h / 40.0));
        for (double v = Math.ceil(lo / step) * step; v <= hi; v += step) {
            int y = TOP + (int) Math.round((hi - v) / (hi - lo) * h);
            gc.drawLine(LEFT - 4, y, LEFT, y);
            String label = String.format(Locale.ROOT, step >= 1 ? "%.0f" : step >= 0.1 ? "%.1f" : step >= 0.01 ? "%.2f" : "%.3g", v);
            gc.drawString(label, LEFT - 6 - gc.textExtent(label).x, y - 7, true);
        }
        double seconds = (to - from) / 1e9;
        double tStep = TimelineCanvas.niceStep(seconds / Math.max(1, plotWidth() / 80.0));
        double first = Math.ceil((from - origin) / 1e9 / tStep) * tStep;
        for (double s = first; origin + s * 1e9 <= to; s += tStep) {
            int x = xOf(origin + Math.round(s * 1e9));
            gc.drawLine(x, TOP + h, x, TOP + h + 4);
            gc.drawString(String.format(Locale.ROOT, tStep >= 1 ? "%.0f s" : "%.1f s", s), x + 2, TOP + h + 4, true);
        }
    }
}
