package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.replay.analysis.Series;
import org.stagecraft.replay.ui.PlotView;
import org.stagecraft.replay.ui.SessionLogEditor;

/** The Plot view on a Session Log: series from typed text, bounded points, the replay cursor, seeking by click. */
@Timeout(180)
class PlotViewTest {
    private IWorkbenchPage page;

    @BeforeEach
    void page() {
        page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
    }

    @AfterEach
    void close() {
        page.closeAllEditors(false);
    }

    @Test
    void seriesOfTheLogWithTheReplayCursor() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.trace());
        PlotView plot = e.showPlot();
        assertSame(e, plot.editor());
        for (String s : List.copyOf(plot.seriesTexts())) {
            plot.removeSeries(s);
        }
        plot.addSeries("position2d.pos.px");
        plot.addSeries("ranger:0 min(ranges)");
        assertThrows(IllegalArgumentException.class, () -> plot.addSeries("lazer.ranges"));
        Ui.spinUntil(() -> !plot.sampling() && plot.series().size() == 2 && plot.series().stream().allMatch(s -> s.size() > 0),
                30_000, "both series sampled");
        int width = plot.canvas().plotWidth();
        for (Series s : plot.series()) {
            assertTrue(s.size() <= 2 * Math.max(16, width / 2), s.spec().label() + ": " + s.size() + " points for " + width + " px");
            assertTrue(s.matched() > 100, s.spec().label() + " samples: " + s.matched());
        }
        assertEquals("position2d.pos.px", plot.series().get(0).spec().label());
        double[] range = plot.series().get(1).range();
        assertTrue(range[0] >= 0 && range[1] < 10, "sonar minimum in metres: " + range[0] + ".." + range[1]);

        // the cursor follows the replay, a click seeks it
        long middle = (e.log().startNanos() + e.log().endNanos()) / 2;
        e.replayer().seek(middle);
        Ui.spinUntil(() -> plot.canvas().cursor() == middle, 5_000, "the plot's cursor to follow the replay");
        var canvas = plot.canvas().control();
        var click = new org.eclipse.swt.widgets.Event();
        click.button = 1;
        click.x = canvas.getClientArea().width - 20;
        click.y = canvas.getClientArea().height / 2;
        long target = plot.canvas().timeAt(click.x);
        canvas.notifyListeners(org.eclipse.swt.SWT.MouseDown, click);
        assertEquals(target, e.replayer().position());
        assertTrue(target > middle);
        page.hideView(plot);
    }

    /**
     * A derived stream (the test's RangerMinimum processor, run on the editor's bus like every
     * contributed processor) is in no log: the plot records it from the bus as the replay publishes it,
     * and its values are the minimum of the logged ranger readings at the same times.
     */
    @Test
    void aDerivedStreamIsPlottedAsTheReplayPublishesIt() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.trace());
        PlotView plot = e.showPlot();
        for (String s : List.copyOf(plot.seriesTexts())) {
            plot.removeSeries(s);
        }
        plot.addSeries("type=128 dev=62 index=0 | value");
        Ui.spinUntil(() -> !plot.sampling() && plot.series().size() == 1, 30_000, "the log sampled");
        assertEquals(0, plot.series().get(0).size(), "no derived stream in the log itself");

        e.replayer().setSpeed(16);
        e.replayer().play();
        long five = e.log().startNanos() + 5_000_000_000L;
        Ui.spinUntil(() -> e.replayer().position() >= five, 30_000, "five seconds of replay");
        e.replayer().pause();
        Ui.spinUntil(() -> plot.series().get(0).size() > 10, 10_000, "recorded points of the derived stream");

        Series derived = plot.series().get(0);
        java.util.Map<Long, Double> expected = new java.util.HashMap<>();
        try (var c = e.log().cursor(e.log().startNanos())) {
            for (var m = c.next(); m != null && m.timeNanos() <= e.replayer().position(); m = c.next()) {
                if (m.decoded() != null && e.columns().device(m).equals("ranger:0") && m.decoded().header().type() == 1
                        && m.decoded().header().subtype() == 1) {
                    expected.put(m.timeNanos(), RangerMinimum.MIN.evaluate(m.decoded().body()).getAsDouble());
                }
            }
        }
        for (int i = 0; i < derived.size(); i++) {
            assertEquals(expected.get(derived.times()[i]), derived.values()[i], "point " + i + " at " + derived.times()[i]);
        }
        page.hideView(plot);
    }
}
