package org.stagecraft.views.tests;

import java.util.function.BooleanSupplier;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.stagecraft.tests.support.UiWait;
import org.stagecraft.views.FramePixels;
import org.stagecraft.views.GlSurfaces;
import org.stagecraft.views.RobotScene;

import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLEventListener;
import com.jogamp.opengl.swt.GLCanvas;

/**
 * A bare shell with a Robot View GL canvas (the same JOGL canvas and capabilities as the view) that draws
 * a {@link RobotScene} on request and reads the frame back. Runs on the UI thread.
 */
final class GlHarness implements AutoCloseable {
    private final Shell shell;
    private final GLCanvas canvas;
    private RobotScene scene;
    private FramePixels last;
    private boolean readBack = true;
    private long drawn;

    GlHarness(int width, int height) {
        Display display = Display.getDefault();
        shell = new Shell(display, SWT.NO_TRIM | SWT.ON_TOP);
        shell.setLayout(new FillLayout());
        canvas = GlSurfaces.create(shell);
        canvas.addGLEventListener(new GLEventListener() {
            @Override
            public void init(GLAutoDrawable d) {
                d.getGL().setSwapInterval(0);
            }

            @Override
            public void display(GLAutoDrawable d) {
                if (scene != null) {
                    scene.render(d.getGL().getGL2(), d.getSurfaceWidth(), d.getSurfaceHeight());
                    drawn++;
                    if (readBack) {
                        last = FramePixels.read(d.getGL(), d.getSurfaceWidth(), d.getSurfaceHeight());
                    }
                }
            }

            @Override
            public void reshape(GLAutoDrawable d, int x, int y, int w, int h) {
            }

            @Override
            public void dispose(GLAutoDrawable d) {
                if (scene != null) {
                    scene.disposeGl(d.getGL().getGL2());
                }
            }
        });
        shell.setBounds(0, 0, width, height);
        shell.open();
        spinUntil(() -> canvas.isVisible() && canvas.getSize().x == width, 10_000, "the GL shell to show");
    }

    /** Renders {@code s} once and returns the frame read back from the back buffer. */
    FramePixels frame(RobotScene s) {
        scene = s;
        last = null;
        readBack = true;
        canvas.display();
        if (last == null) {
            throw new AssertionError("the canvas did not draw (no GL context?)");
        }
        return last;
    }

    /** Renders and swaps without reading back (the benchmark: as the view draws). */
    void frame(RobotScene s, boolean read) {
        scene = s;
        readBack = read;
        long before = drawn;
        canvas.display();
        if (drawn == before) {
            throw new AssertionError("the canvas did not draw");
        }
    }

    static void spinUntil(BooleanSupplier condition, long timeoutMillis, String what) {
        UiWait.spinUntil(condition, timeoutMillis, what);
    }

    @Override
    public void close() {
        if (scene != null && !canvas.isDisposed()) {
            canvas.destroy(); // GLEventListener.dispose runs with the context current
        }
        shell.dispose();
    }
}
