package org.stagecraft.pydev.tests;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashSet;
import java.util.List;
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
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.debug.core.model.IStackFrame;
import org.eclipse.debug.core.model.IThread;
import org.eclipse.debug.ui.DebugUITools;
import org.eclipse.debug.ui.IDebugUIConstants;
import org.eclipse.debug.ui.IDebugView;
import org.eclipse.e4.ui.model.application.ui.MUIElement;
import org.eclipse.e4.ui.model.application.ui.advanced.MPerspective;
import org.eclipse.e4.ui.model.application.ui.advanced.MPlaceholder;
import org.eclipse.e4.ui.model.application.ui.basic.MPartStack;
import org.eclipse.e4.ui.model.application.ui.basic.MWindow;
import org.eclipse.e4.ui.workbench.modeling.EModelService;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.part.FileEditorInput;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.views.RobotView;

/**
 * Pictures of the workbench while the robot program is suspended and its robot held, saved as PNG (SWT GC copyArea of the
 * shell, ImageLoader): {@link #capture} the session's spy log (still being written) in the Session Log editor, with its
 * holds on the timeline, and a Robot View following the live session (docs/debugging-robots.md); {@link #captureDebugging}
 * the program in PyDev's editor at the current instruction, the Debug view and the Robot View (docs/tool-manager.md).
 * Side outputs of RealStageHoldTest: the waits for what they show give up quietly (the test's own assertions decide).
 */
final class WorkbenchShot {
    private static final Duration WAIT = Duration.ofSeconds(60);

    private WorkbenchShot() {
    }

    /**
     * Before a debug launch: the workbench arranged as a user debugging a robot program would (1280x1024; the Debug view
     * open in the left stack, so that at a suspension the debug UI selects the top stack frame and shows it in the
     * program's editor; the Outline closed, room for the Robot View) and the Debug perspective not switched to at suspension.
     */
    static void arrangeForDebugging(IFile program) throws Exception {
        IEclipsePreferences debugUi = InstanceScope.INSTANCE.getNode(IDebugUIConstants.PLUGIN_ID);
        debugUi.put(IDebugUIConstants.PLUGIN_ID + ".switch_perspective_on_suspend", "never");
        debugUi.flush();
        AtomicReference<Exception> failure = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                IWorkbenchWindow window = PlatformUI.getWorkbench().getActiveWorkbenchWindow();
                IWorkbenchPage page = window.getActivePage();
                window.getShell().setBounds(0, 0, 1280, 1024);
                var outline = page.findView(IPageLayout.ID_OUTLINE);
                if (outline != null) {
                    page.hideView(outline);
                }
                page.showView(IDebugUIConstants.ID_DEBUG_VIEW);
                moveToLeftStack(window, IDebugUIConstants.ID_DEBUG_VIEW);
                page.showView(RobotView.ID, null, IWorkbenchPage.VIEW_VISIBLE);
                page.showView(IDebugUIConstants.ID_DEBUG_VIEW, null, IWorkbenchPage.VIEW_VISIBLE);
                IEditorPart editor = page.findEditor(new FileEditorInput(program));
                if (editor == null) {
                    editor = IDE.openEditor(page, program);
                }
                page.activate(editor);
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
    }

    /** Moves the view's placeholder into the perspective's left stack (the Project Explorer's), if both are there. */
    private static void moveToLeftStack(IWorkbenchWindow window, String viewId) {
        EModelService models = window.getService(EModelService.class);
        MWindow mWindow = window.getService(MWindow.class);
        if (models == null || mWindow == null) {
            return;
        }
        MPerspective perspective = models.getActivePerspective(mWindow);
        MUIElement left = perspective == null ? null : models.find("org.stagecraft.ui.left", perspective);
        List<MPlaceholder> views = perspective == null ? List.of() : models.findElements(perspective, viewId, MPlaceholder.class, null);
        if (left instanceof MPartStack stack && !views.isEmpty()) {
            MPlaceholder view = views.get(0);
            Object parent = view.getParent();
            if (parent != stack) {
                models.move(view, stack);
            }
            stack.setVisible(true);
            stack.setToBeRendered(true);
        }
    }

    /**
     * At a suspension: the program in its (PyDev's) editor with the current instruction, the Debug view with the suspended
     * thread's top frame selected (as the debug UI selected it; selected here only if it did not within the wait) and the
     * Robot View; saves the shell's picture to {@code png}, returns its colour count.
     */
    static int captureDebugging(IFile program, IThread thread, Path png) throws Exception {
        Display display = Display.getDefault();
        IStackFrame top = thread.getTopStackFrame();
        if (!soft(Duration.ofSeconds(15), () -> ui(() -> DebugUITools.getDebugContext() instanceof IStackFrame f && thread.equals(f.getThread())))) {
            display.syncExec(() -> {
                IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
                if (page.findView(IDebugUIConstants.ID_DEBUG_VIEW) instanceof IDebugView v) {
                    v.getViewer().setSelection(new StructuredSelection(top), true);
                }
            });
            soft(Duration.ofSeconds(10), () -> ui(() -> DebugUITools.getDebugContext() instanceof IStackFrame f && thread.equals(f.getThread())));
        }
        soft(Duration.ofSeconds(15), () -> ui(() -> {
            IEditorPart e = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage().getActiveEditor();
            return e != null && program.equals(e.getEditorInput().getAdapter(IFile.class));
        }));
        AtomicReference<RobotView> view = new AtomicReference<>();
        display.syncExec(() -> {
            try {
                IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
                view.set((RobotView) page.showView(RobotView.ID, null, IWorkbenchPage.VIEW_VISIBLE));
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        awaitDrawn(view.get());
        return save(png, () -> true);
    }

    /**
     * At a robot data breakpoint's suspension: the Breakpoints view with the breakpoint and its last hit, the Debug view
     * with the suspended thread, the Robot View; saves the shell's picture to {@code png}, returns its colour count.
     */
    static int captureDataBreakpoint(IThread thread, Path png) throws Exception {
        Display display = Display.getDefault();
        soft(Duration.ofSeconds(15), () -> ui(() -> DebugUITools.getDebugContext() instanceof IStackFrame f && thread.equals(f.getThread())));
        AtomicReference<RobotView> view = new AtomicReference<>();
        display.syncExec(() -> {
            try {
                IWorkbenchWindow window = PlatformUI.getWorkbench().getActiveWorkbenchWindow();
                IWorkbenchPage page = window.getActivePage();
                view.set((RobotView) page.showView(RobotView.ID, null, IWorkbenchPage.VIEW_VISIBLE));
                page.showView(IDebugUIConstants.ID_BREAKPOINT_VIEW, null, IWorkbenchPage.VIEW_VISIBLE);
                // in the consoles' stack, where the picture shows it whole (the perspective keeps it in a narrow stack)
                EModelService models = window.getService(EModelService.class);
                MWindow mWindow = window.getService(MWindow.class);
                MPerspective perspective = models == null || mWindow == null ? null : models.getActivePerspective(mWindow);
                if (perspective != null) {
                    List<MPlaceholder> robot = models.findElements(perspective, "org.eclipse.ui.console.ConsoleView", MPlaceholder.class,
                            null);
                    List<MPlaceholder> breakpoints = models.findElements(perspective, IDebugUIConstants.ID_BREAKPOINT_VIEW,
                            MPlaceholder.class, null);
                    Object consoles = robot.isEmpty() ? null : robot.get(0).getParent();
                    if (consoles instanceof MPartStack stack && !breakpoints.isEmpty() && breakpoints.get(0).getParent() != consoles) {
                        models.move(breakpoints.get(0), stack);
                    }
                }
                page.showView(IDebugUIConstants.ID_BREAKPOINT_VIEW, null, IWorkbenchPage.VIEW_ACTIVATE);
                page.showView(IDebugUIConstants.ID_DEBUG_VIEW, null, IWorkbenchPage.VIEW_VISIBLE);
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        awaitDrawn(view.get());
        // the Breakpoints view labels its rows in the background: wait for the breakpoint's text
        soft(Duration.ofSeconds(15), () -> ui(() -> PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage()
                .findView(IDebugUIConstants.ID_BREAKPOINT_VIEW) instanceof IDebugView v
                && v.getViewer().getControl() instanceof org.eclipse.swt.widgets.Tree tree && tree.getItemCount() > 0
                && tree.getItem(0).getText().startsWith("Robot data:")));
        return save(png, () -> true);
    }

    /** The reading the workbench's Robot View marks (a robot data breakpoint's), or null (none, or no Robot View). */
    static org.stagecraft.scene.BreakReading markedReading() {
        return ui(() -> PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage().findView(RobotView.ID) instanceof RobotView r
                ? r.breakReading() : null);
    }

    /** Opens the views and the log, waits until they have drawn, and saves the shell's picture to {@code png}; returns its colour count. */
    static int capture(IProject project, Path png) throws Exception {
        return captureAt(project, -1, png);
    }

    /**
     * As {@link #capture(IProject, Path)}, with the Session Log editor moved to {@code timeNanos} (the log's clock; -1:
     * where it opens), so its inspector shows the messages there.
     */
    static int captureAt(IProject project, long timeNanos, Path png) throws Exception {
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
                var debug = page.findView(IDebugUIConstants.ID_DEBUG_VIEW);
                if (debug != null) {
                    page.hideView(debug); // (the picture at the first suspension has it)
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
        awaitShown(editor.get());
        // the holds on the timeline: a log read before the spy's chunk with them was written shows none; read it again
        Supplier<Boolean> holds = () -> ui(() -> !(Boolean) call(call(call(editor.get(), "timeline"), "holds"), "isEmpty"));
        for (int i = 0; i < 5 && !soft(Duration.ofSeconds(3), holds); i++) {
            display.syncExec(() -> editor.get().reload());
            soft(Duration.ofSeconds(2), () -> ui(() -> editor.get().reading() || !editor.get().timelineComplete()));
            awaitShown(editor.get());
        }
        Supplier<Boolean> ready = () -> shown(editor.get());
        if (timeNanos >= 0) {
            // by reflection, as above: the replay session's transport is the editor's own (not this bundle's API); the editor
            // may read the log once more as its writer closes it, which starts it again from the beginning: seek until it stays
            Supplier<Boolean> there = () -> ui(() -> {
                Object replayer = call(editor.get(), "replayer");
                return replayer != null && Math.abs(((Number) call(replayer, "position")).longValue() - timeNanos) < 1_000_000_000L;
            });
            for (int i = 0; i < 10 && !there.get(); i++) {
                display.syncExec(() -> {
                    Object transport = call(call(editor.get(), "session"), "transport");
                    try {
                        transport.getClass().getMethod("seek", long.class).invoke(transport, timeNanos);
                    } catch (ReflectiveOperationException ex) {
                        throw new AssertionError("seek: " + ex, ex);
                    }
                });
                awaitShown(editor.get());
            }
            Await.until("the Session Log editor at the triggering message", WAIT, there::get, () -> "");
            ready = () -> shown(editor.get()) && there.get(); // the picture only while it is there
        }
        awaitDrawn(view.get());
        // the editor reads a growing log again by itself: the picture is taken when it shows a complete reading
        return save(png, ready);
    }

    /** What SessionLogEditorTest waits for: the timeline showing the messages, the inspector's first window (by reflection:
     * those accessors are the editor's internal ones, for its own tests). */
    private static void awaitShown(SessionLogEditor e) {
        Await.until("the Session Log editor to read the live spy log", WAIT, () -> ui(() -> !e.reading() && e.timelineComplete()), () -> "");
        Await.until("the Session Log editor's timeline and inspector to show the log", WAIT, () -> ui(() -> shown(e)), () -> "");
    }

    /** UI thread. */
    private static boolean shown(SessionLogEditor e) {
        Object snapshot = call(call(e, "timeline"), "snapshot");
        return !e.reading() && snapshot != null && ((Number) call(snapshot, "messages")).longValue() > 0 && e.timelineComplete()
                && !(Boolean) call(call(call(e, "inspector"), "window"), "isEmpty");
    }

    /** The robots the workbench's Robot View knows (for the test's report). */
    static String robots() {
        return ui(() -> {
            var v = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage().findView(RobotView.ID);
            return v instanceof RobotView r && r.scene() != null ? String.valueOf(r.scene().world().robots()) : "(no Robot View)";
        });
    }

    private static void awaitDrawn(RobotView view) {
        Await.until("the Robot View to draw", WAIT, () -> ui(() -> view.frames() > 0), () -> "");
        long frames = ui(() -> view.frames());
        Display.getDefault().syncExec(() -> view.requestRedraw());
        Await.until("the Robot View to draw again", WAIT, () -> ui(() -> view.frames() > frames), () -> "");
    }

    /** Whether {@code condition} held within {@code timeout} (false, not a failure, if it did not). */
    private static boolean soft(Duration timeout, Supplier<Boolean> condition) throws InterruptedException {
        long end = System.nanoTime() + timeout.toNanos();
        while (System.nanoTime() < end) {
            if (Boolean.TRUE.equals(condition.get())) {
                return true;
            }
            Thread.sleep(100);
        }
        return false;
    }

    /** Saves the shell's picture to {@code png}; returns its colour count (every 4th pixel). */
    private static int save(Path png, Supplier<Boolean> ready) throws Exception {
        Display display = Display.getDefault();
        AtomicReference<ImageData> data = new AtomicReference<>();
        for (int tries = 0; tries < 100 && data.get() == null; tries++) {
            if (tries > 0) {
                Thread.sleep(100);
            }
            boolean last = tries == 99; // then as it is
            display.syncExec(() -> {
                boolean before = ready.get();
                while (display.readAndDispatch()) {
                    // let the parts paint what they have
                }
                if (!last && !(before && ready.get())) {
                    return;
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
        }
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
