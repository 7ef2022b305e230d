package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.eclipse.e4.ui.model.application.ui.basic.MPart;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.views.RobotView;

import com.jogamp.opengl.swt.GLCanvas;

/**
 * Issue 24, item 4: the Robot View's GL area shows its own picture again once a window that covered it
 * goes away, with no new data arriving (a held robot sends none): before, it kept the pixels of whatever
 * had covered it (closed dialogs, Stage's window) until the next data came. Read from the screen, as the
 * user sees it, not from the view's own frame.
 */
@Timeout(120)
class CanvasExposeTest {
    /** The cover's colour: nothing the view draws is this magenta. */
    private static final int COVER = 0xFF00FF;
    /** The scene's background grey (RobotScene.BACKGROUND, 0.92). */
    private static final int BACKGROUND = 0xEBEBEB;

    @Test
    void aCoveredAndUncoveredViewShowsItsPictureAgainWithoutNewData() throws Exception {
        IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
        RobotView view = (RobotView) page.showView(RobotView.ID, "expose", IWorkbenchPage.VIEW_ACTIVATE);
        try {
            GlHarness.spinUntil(() -> view.frames() > 0, 10_000, "the view's first frame");
            Display display = Display.getCurrent();
            GLCanvas canvas = find((Control) view.getSite().getService(MPart.class).getWidget());
            assertNotNull(canvas, "the view has a GL canvas");
            Rectangle area = display.map(canvas, null, canvas.getClientArea());
            assertTrue(area.width > 50 && area.height > 50, "the canvas is on screen: " + area);
            Rectangle probe = new Rectangle(area.x + area.width / 4, area.y + area.height / 4, area.width / 2, area.height / 2);
            GlHarness.spinUntil(() -> count(screen(display, probe), COVER) == 0, 5_000, "the view on screen");

            Shell cover = new Shell(canvas.getShell(), SWT.NO_TRIM | SWT.ON_TOP);
            cover.setBackground(new org.eclipse.swt.graphics.Color(255, 0, 255));
            cover.setBounds(area);
            cover.open();
            int total = probe.width * probe.height;
            GlHarness.spinUntil(() -> count(screen(display, probe), COVER) > total * 9 / 10, 10_000,
                    "the cover on screen over the view");
            long frames = view.frames();
            cover.dispose();
            GlHarness.spinUntil(() -> count(screen(display, probe), COVER) == 0, 10_000,
                    "the view to show its own picture again (frames before the cover went: " + frames + ", now "
                            + view.frames() + "; cover pixels left: " + count(screen(display, probe), COVER) + " of " + total + ")");
            // its own picture, not a toolkit's background: the scene's grey and grid
            GlHarness.spinUntil(() -> count(screen(display, probe), BACKGROUND) > total / 2, 10_000,
                    "the view's background again: " + count(screen(display, probe), BACKGROUND) + " of " + total);
            System.out.println("[expose] frames before the cover went " + frames + ", after " + view.frames());
        } finally {
            page.hideView(view);
        }
    }

    private static GLCanvas find(Control c) {
        if (c instanceof GLCanvas g) {
            return g;
        }
        if (c instanceof Composite parent) {
            for (Control child : parent.getChildren()) {
                GLCanvas g = find(child);
                if (g != null) {
                    return g;
                }
            }
        }
        return null;
    }

    private static ImageData screen(Display display, Rectangle r) {
        Image image = new Image(display, r.width, r.height);
        GC gc = new GC(display);
        try {
            gc.copyArea(image, r.x, r.y);
            return image.getImageData();
        } finally {
            gc.dispose();
            image.dispose();
        }
    }

    private static int count(ImageData d, int rgb) {
        int n = 0;
        for (int y = 0; y < d.height; y++) {
            for (int x = 0; x < d.width; x++) {
                org.eclipse.swt.graphics.RGB p = d.palette.getRGB(d.getPixel(x, y));
                n += Math.abs(p.red - (rgb >> 16 & 0xFF)) <= 3 && Math.abs(p.green - (rgb >> 8 & 0xFF)) <= 3
                        && Math.abs(p.blue - (rgb & 0xFF)) <= 3 ? 1 : 0;
            }
        }
        return n;
    }
}
