package org.stagecraft.pydev.tests;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import java.util.stream.Stream;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.views.RobotView;

/**
 * A picture of the workbench while the robot program is suspended and its robot held: the session's spy log (still being written) in the Session Log editor, and a Robot View following the
 * live session. Saved as PNG (SWT GC copyArea of the shell, ImageLoader) for docs/debugging-robots.md.
 */
final class WorkbenchShot {
    private static final Duration WAIT = Duration.ofSeconds(60);

    private WorkbenchShot() {
    }

    /** Opens the views and the log, waits until they have drawn, and saves the shell's picture to {@code png}; returns its colour count. */
    static int capture(IProject project, Path png) throws Exception {
        Display display = Display.getDefault();
        project.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());
        Path logs = project.getLocation().toPath().resolve("logs");
        String name;
        try (Stream<Path> s = Files.list(logs)) {
            name = s.filter(p -> p.toString().endsWith(".mcap")).findFirst().orElseThrow().getFileName().toString();
        }
        IFile log = project.getFile("logs/" + name);
        AtomicReference<SessionLogEditor> editor = new AtomicReference<>();
        AtomicReference<RobotView> view = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        display.syncExec(() -> {
            try {
                IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
                page.getWorkbenchWindow().getShell().setBounds(0, 0, 1280, 1024);
                var explorer = page.findView(org.eclipse.ui.IPageLayout.ID_PROJECT_EXPLORER);
                if (explorer != null) {
                    page.hideView(explorer); // room for the log and the Robot View
                }
                editor.set((SessionLogEditor) IDE.openEditor(page, log, SessionLogEditor.ID, true));
                view.set((RobotView) page.showView(RobotView.ID));
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        Await.until("the Session Log editor to read the live spy log", WAIT,
                () -> ui(() -> !editor.get().reading() && editor.get().timelineComplete()), () -> "");
        // what SessionLogEditorTest waits for: the timeline showing the messages, the inspector's first window
        // (by reflection: those accessors are the editor's internal ones, for its own tests)
        Await.until("the Session Log editor's timeline and inspector to show the log", WAIT, () -> ui(() -> {
            SessionLogEditor e = editor.get();
            Object snapshot = call(call(e, "timeline"), "snapshot");
            return snapshot != null && ((Number) call(snapshot, "messages")).longValue() > 0 && e.timelineComplete()
                    && !(Boolean) call(call(call(e, "inspector"), "window"), "isEmpty");
        }), () -> "");
        Await.until("the Robot View to draw", WAIT, () -> ui(() -> view.get().frames() > 0), () -> "");
        long frames = ui(() -> view.get().frames());
        display.syncExec(() -> view.get().requestRedraw());
        Await.until("the Robot View to draw again", WAIT, () -> ui(() -> view.get().frames() > frames), () -> "");
        AtomicReference<ImageData> data = new AtomicReference<>();
        display.syncExec(() -> {
            while (display.readAndDispatch()) {
                // let the parts paint what they have
            }
            Shell shell = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell();
            Rectangle b = shell.getBounds();
            Image image = new Image(display, b.width, b.height);
            GC gc = new GC(display);
            try {
                gc.copyArea(image, b.x, b.y);
            } finally {
                gc.dispose();
            }
            data.set(image.getImageData());
            image.dispose();
        });
        Set<Integer> colours = new HashSet<>();
        ImageData d = data.get();
        for (int y = 0; y < d.height; y += 4) {
            for (int x = 0; x < d.width; x += 4) {
                colours.add(d.getPixel(x, y));
            }
        }
        Files.createDirectories(png.toAbsolutePath().getParent());
        ImageLoader saver = new ImageLoader();
        saver.data = new ImageData[] {d};
        saver.save(png.toString(), SWT.IMAGE_PNG);
        return colours.size();
    }

    private static Object call(Object target, String method) {
        try {
            return target.getClass().getMethod(method).invoke(target);
        } catch (ReflectiveOperationException ex) {
            throw new AssertionError(target.getClass().getName() + "." + method + "(): " + ex, ex);
        }
    }

    private static <T> T ui(Supplier<T> s) {
        AtomicReference<T> r = new AtomicReference<>();
        Display.getDefault().syncExec(() -> r.set(s.get()));
        return r.get();
    }
}
