package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;

import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.replay.ui.PlotView;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.views.RobotView;

/**
 * The picture in docs/replay-ui.md: the workbench with the Session Log editor on the shared recording
 * (replay at 12 s, a laser scan selected in the inspector), a Robot View following it and a Plot. Saved
 * to target/screenshots/session-log-editor.png; the test checks it holds a real picture.
 */
@Timeout(180)
class EditorScreenshotTest {
    @Test
    void theEditorWithARobotViewAndAPlot() throws Exception {
        IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
        Shell shell = page.getWorkbenchWindow().getShell();
        shell.setBounds(0, 0, 1280, 1024);
        // room for the editor: the explorer and the outline have nothing to say here
        for (String id : new String[] { org.eclipse.ui.IPageLayout.ID_PROJECT_EXPLORER, org.eclipse.ui.IPageLayout.ID_OUTLINE,
                RobotView.ID }) { // the perspective's Robot View follows Live: nothing to show here
            var v = page.findView(id);
            if (v != null) {
                page.hideView(v);
            }
        }
        try {
            SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.trace());
            SessionLogEditorTest.waitForTimeline(e);
            RobotView view = e.showInRobotView();
            PlotView plot = e.showPlot();
            for (String s : java.util.List.copyOf(plot.seriesTexts())) {
                plot.removeSeries(s);
            }
            plot.addSeries("position2d.pos.px");
            plot.addSeries("position2d.pos.py");
            plot.addSeries("ranger:0 min(ranges)");
            page.activate(e);
            e.replayer().setSpeed(16);
            e.replayer().play();
            long twelve = e.log().startNanos() + 12_000_000_000L;
            Ui.spinUntil(() -> e.replayer().position() >= twelve, 30_000, "the replay to reach 12 s");
            e.replayer().pause();
            e.inspector().setFilter("laser:0", "");
            Ui.spinUntil(() -> !e.inspector().window().isEmpty()
                    && e.inspector().window().rows().stream().allMatch(r -> e.columns().device(r.message()).equals("laser:0")),
                    30_000, "the laser rows");
            int row = Math.min(e.inspector().window().anchorIndex(), e.inspector().window().rows().size() - 1);
            e.inspector().selectRow(Math.max(0, row - 1));
            Ui.spinUntil(() -> !plot.sampling() && plot.series().size() == 3, 30_000, "the plot");
            Ui.spinUntil(() -> e.inspector().statusText().contains("entries"), 30_000, "the inspector to settle");
            Ui.spinUntil(() -> view.scene().world().robots().stream().anyMatch(r -> r.poseSeen()), 30_000,
                    "the Robot View's world to see the robot: " + view.scene().world().robots());
            page.bringToTop(view);
            page.bringToTop(plot);
            Ui.spinUntil(() -> view.frames() > 0, 30_000, "the Robot View to draw");
            view.requestRedraw();
            Ui.drain();

            Rectangle b = shell.getBounds();
            Image image = new Image(shell.getDisplay(), b.width, b.height);
            GC gc = new GC(shell.getDisplay());
            try {
                gc.copyArea(image, b.x, b.y);
            } finally {
                gc.dispose();
            }
            ImageData data = image.getImageData();
            image.dispose();
            Set<Integer> colours = new HashSet<>();
            for (int y = 0; y < data.height; y += 4) {
                for (int x = 0; x < data.width; x += 4) {
                    colours.add(data.getPixel(x, y));
                }
            }
            assertTrue(colours.size() > 50, "a real picture, not a blank screen: " + colours.size() + " colours");
            Path dir = Path.of("target", "screenshots");
            Files.createDirectories(dir);
            ImageLoader saver = new ImageLoader();
            saver.data = new ImageData[] { data };
            saver.save(dir.resolve("session-log-editor.png").toString(), SWT.IMAGE_PNG);
            page.hideView(plot);
            page.hideView(view);
        } finally {
            page.closeAllEditors(false);
        }
    }
}
