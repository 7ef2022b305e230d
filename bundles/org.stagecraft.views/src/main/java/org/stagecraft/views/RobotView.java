package org.stagecraft.views;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.action.Action;
import org.eclipse.jface.action.IAction;
import org.eclipse.jface.action.IMenuManager;
import org.eclipse.jface.action.MenuManager;
import org.eclipse.jface.action.Separator;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.RGB;
import org.eclipse.swt.widgets.ColorDialog;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Event;
import org.eclipse.ui.IMemento;
import org.eclipse.ui.IViewSite;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.part.ViewPart;
import org.stagecraft.core.streams.BusSources;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.scene.BreakReading;
import org.stagecraft.scene.Camera;
import org.stagecraft.scene.DefaultLayers;
import org.stagecraft.scene.HoldStatus;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.RobotId;
import org.stagecraft.scene.RobotState;
import org.stagecraft.scene.ViewSetup;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.views.internal.RedrawThrottle;
import org.stagecraft.views.internal.SensorConditions;
import org.stagecraft.streams.StreamMessage;
import org.eclipse.jface.dialogs.MessageDialog;
import org.stagecraft.views.internal.ViewMemento;

import com.jogamp.opengl.GL2;
import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLEventListener;
import com.jogamp.opengl.swt.GLCanvas;

/**
 * The Robot View: one OpenGL canvas showing the robots of the workbench's stream bus in the world frame,
 * through layers (a renderer bound to a stream pattern each). All views share the bus's world model
 * ({@link SharedWorld}), so a view opened late still knows the sensor geometry seen before. Any number can be open (secondary ids);
 * each keeps its layers and camera in its memento across workbench restarts.
 *
 * <p>Mouse: drag to pan, wheel to zoom at the pointer, double-click a robot to follow it (elsewhere: stop
 * following). The view menu holds the layers (visibility, colour, opacity, order), follow and reset, and
 * the source: the workbench bus ("Live") or the replay of an open Session Log ({@link BusSources}). The
 * chosen source is remembered; while it is not open the view shows Live and goes back to it when it
 * opens again.
 */
public class RobotView extends ViewPart {
    public static final String ID = "org.stagecraft.views.robot";
    /** At most this many frames per second; data arriving faster is merged (newest wins). */
    public static final int MAX_FPS = 60;
    /** Memento attribute holding the followed source's id. */
    static final String SOURCE = "source";

    private static final ILog LOG = ILog.of(Platform.getBundle("org.stagecraft.views"));

    private @Nullable ViewSetup restored;
    /** The source chosen (may be a log that is not open now); {@link #bus} is what the view follows. */
    private String sourceId = BusSources.LIVE;
    private @Nullable StreamBus bus;
    private @Nullable AutoCloseable sourcesListener;
    private @Nullable SharedWorld shared;
    private @Nullable AutoCloseable worldListener;
    private @Nullable RobotScene scene;
    /** Whether the source's robots are held (robot hold), drawn over the robots. */
    private @Nullable HoldStatus holdStatus;
    private @Nullable GLCanvas canvas;
    private @Nullable RedrawThrottle redraw;
    private @Nullable Consumer<FramePixels> readback;
    private int dragX, dragY;
    private boolean dragging;
    /** A new view (no saved camera) follows the first robot it sees, wherever in the world it is. */
    private boolean followFirstRobot;
    /** The world's {@link org.stagecraft.scene.WorldModel#forgetting()} this view last framed robots at. */
    private long forgettingSeen;

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void init(IViewSite site, IMemento memento) throws PartInitException {
        super.init(site, memento);
        if (memento != null) {
            restored = ViewMemento.read(memento, p -> LOG.warn(p));
            String source = memento.getString(SOURCE);
            if (source != null) {
                sourceId = source;
            }
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createPartControl(Composite parent) {
        canvas = GlSurfaces.create(parent);
        redraw = new RedrawThrottle(parent.getDisplay(), 1000 / MAX_FPS, this::drawNow);
        StreamBus bus = chosenBus();
        this.bus = bus;
        shared = SharedWorld.of(bus);
        scene = new RobotScene(shared.world(), new Camera(), redraw::request);
        worldListener = shared.listen(redraw::request);
        applySetup(restored != null ? restored : new ViewSetup(DefaultLayers.create(), Map.of()));
        followFirstRobot = restored == null;
        forgettingSeen = shared.world().forgetting();
        canvas.addGLEventListener(new Drawer());
        installMouse();
        installMenu();
        installContextMenu();
        scene.connect(bus, false); // the world model is the bus's shared one
        followHolds();
        var display = parent.getDisplay();
        sourcesListener = BusSources.listen(() -> {
            if (!display.isDisposed()) {
                display.asyncExec(this::attach); // sources change on any thread (an editor closing, a session ending)
            }
        });
        describeSource();
        redraw.request();
    }

    /** The id of the source chosen ({@link BusSources#LIVE} or a log's), whether or not it is open now. */
    public String sourceId() {
        return sourceId;
    }

    /** The bus the view follows now. */
    public @Nullable StreamBus bus() {
        return bus;
    }

    /** Follows the source with that id (Live while it is not open). UI thread. */
    public void followSource(@Nullable String id) {
        sourceId = id == null ? BusSources.LIVE : id;
        attach();
    }

    private StreamBus chosenBus() {
        return BusSources.find(sourceId).map(BusSources.Source::bus).orElseGet(WorkbenchBus::get);
    }

    /** Moves to the chosen source's bus if that changed (chosen, opened or closed), with fresh layers. */
    private void attach() {
        if (scene == null || canvas == null || canvas.isDisposed()) {
            return;
        }
        StreamBus target = chosenBus();
        if (target != bus) {
            bus = target;
            closeWorldListener();
            shared = SharedWorld.of(target);
            worldListener = shared.listen(redraw::request);
            scene.reconnect(target, shared.world());
            followHolds();
            applySetup(setup()); // new renderers and feeds: nothing drawn from the old source stays
            followFirstRobot = true; // the new source's robots may have other addresses
            forgettingSeen = shared.world().forgetting();
            redraw.request();
        }
        describeSource();
    }

    /** Follows the hold state of the bus the view shows (a redraw puts the text on or takes it off). */
    private void followHolds() {
        if (holdStatus != null) {
            holdStatus.close();
        }
        holdStatus = new HoldStatus(Objects.requireNonNull(bus), redraw::request);
    }

    /** What the view writes over the robots about the robot hold, or null (for tests). */
    public @Nullable String holdText() {
        return holdStatus == null ? null : holdStatus.overlayText();
    }

    /** The reading a robot data breakpoint stopped on, which the view marks, or null (for tests). */
    public @Nullable BreakReading breakReading() {
        return holdStatus == null ? null : holdStatus.breakReading();
    }

    private void describeSource() {
        if (BusSources.LIVE.equals(sourceId)) {
            setContentDescription("");
            return;
        }
        setContentDescription(BusSources.find(sourceId).map(s -> "Source: " + s.label())
                .orElse("Source: " + sourceId + " is not open; showing Live"));
    }

    public @Nullable RobotScene scene() {
        return scene;
    }

    /** Frames drawn so far. */
    public long frames() {
        return scene.frames();
    }

    /** The layers and camera as they would be saved. */
    public ViewSetup setup() {
        return new ViewSetup(scene.layers(), scene.camera().toAttributes());
    }

    /** Replaces the layers (renderers from the extension point) and restores the camera. */
    public void applySetup(ViewSetup setup) {
        for (LayerSpec l : scene.layers()) {
            scene.removeLayer(l.id());
        }
        Consumer<IStatus> problems = LOG::log;
        for (Map.Entry<LayerSpec, StreamRenderer> e : RendererExtensionRegistry.instantiate(setup.layers(),
                RendererExtensionRegistry.load(), problems)) {
            scene.addLayer(e.getKey(), e.getValue());
        }
        scene.camera().fromAttributes(setup.camera());
        redraw.request();
    }

    /** Changes one layer (visibility, colour, opacity, order or pattern) and redraws. */
    public void updateLayer(LayerSpec spec) {
        scene.updateLayer(spec);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void saveState(IMemento memento) {
        ViewMemento.write(memento, setup());
        memento.putString(SOURCE, sourceId);
    }

    /** Draws a frame now (UI thread) and returns what it drew, read back from the back buffer. */
    public @Nullable FramePixels capture() {
        FramePixels[] out = new FramePixels[1];
        readback = p -> out[0] = p;
        try {
            canvas.display();
        } finally {
            readback = null;
        }
        return out[0];
    }

    /** Asks for a redraw (merged with pending ones). */
    public void requestRedraw() {
        redraw.request();
    }

    @Override
    public void setFocus() {
        canvas.setFocus();
    }

    @Override
    public void dispose() {
        if (scene != null) {
            scene.close();
        }
        if (holdStatus != null) {
            holdStatus.close();
        }
        closeWorldListener();
        if (sourcesListener != null) {
            try {
                sourcesListener.close();
            } catch (Exception e) {
                LOG.error("Robot View: " + e.getMessage(), e);
            }
        }
        super.dispose(); // the canvas goes with the part; its GLEventListener.dispose frees GPU data
    }

    private void closeWorldListener() {
        if (worldListener != null) {
            try {
                worldListener.close();
            } catch (Exception e) {
                LOG.error("Robot View: " + e.getMessage(), e);
            }
            worldListener = null;
        }
    }

    private void drawNow() {
        long forgetting = scene.world().forgetting();
        if (forgetting != forgettingSeen) {
            // a new session began (its robots replaced the ended ones): frame its first robot, as a new view does
            forgettingSeen = forgetting;
            followFirstRobot = true;
        }
        if (followFirstRobot) {
            scene.world().robots().stream().filter(RobotState::poseSeen).findFirst().ifPresent(r -> {
                followFirstRobot = false;
                scene.camera().follow(r.id());
            });
        }
        if (canvas != null && !canvas.isDisposed() && canvas.isVisible()) {
            canvas.display();
        }
    }

    private final class Drawer implements GLEventListener {
        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void init(GLAutoDrawable d) {
            d.getGL().setSwapInterval(0); // frames are paced by the data, not the (virtual) display
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void display(GLAutoDrawable d) {
            GL2 gl = d.getGL().getGL2();
            int w = d.getSurfaceWidth(), h = d.getSurfaceHeight();
            scene.overlay(holdText());
            scene.mark(breakReading());
            scene.render(gl, w, h);
            Consumer<FramePixels> r = readback;
            if (r != null) {
                r.accept(FramePixels.read(gl, w, h)); // before the swap: the back buffer holds this frame
            }
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void reshape(GLAutoDrawable d, int x, int y, int w, int h) {
            // the scene sets the viewport every frame
        }

        @NonNullByDefault({}) // the parameters as the unannotated library gives them
        @Override
        public void dispose(GLAutoDrawable d) {
            scene.disposeGl(d.getGL().getGL2());
        }
    }

    private void installMouse() {
        canvas.addListener(SWT.MouseDown, e -> {
            if (e.button == 1) {
                followFirstRobot = false; // the user has taken the camera
                dragging = true;
                dragX = e.x;
                dragY = e.y;
            }
        });
        canvas.addListener(SWT.MouseUp, e -> dragging = false);
        canvas.addListener(SWT.MouseMove, e -> {
            if (dragging) {
                scene.camera().pan(e.x - dragX, e.y - dragY);
                dragX = e.x;
                dragY = e.y;
                redraw.request();
            }
        });
        canvas.addListener(SWT.MouseVerticalWheel, e -> {
            Camera c = scene.camera();
            c.zoomAt(e.x + 0.5, c.mouseToWindowY(e.y), e.count > 0 ? 1.25 : 0.8);
            redraw.request();
        });
        canvas.addListener(SWT.MouseDoubleClick, this::followAt);
    }

    private void followAt(Event e) {
        Camera c = scene.camera();
        double x = c.windowToWorldX(e.x + 0.5), y = c.windowToWorldY(c.mouseToWindowY(e.y));
        RobotId nearest = null;
        double best = Math.max(0.5, 20 * c.metresPerPixel());
        for (RobotState r : scene.world().robots()) {
            double d = Math.hypot(r.pose().x() - x, r.pose().y() - y);
            if (d < best) {
                best = d;
                nearest = r.id();
            }
        }
        c.follow(nearest);
        redraw.request();
    }

    private void installMenu() {
        IMenuManager menu = getViewSite().getActionBars().getMenuManager();
        menu.setRemoveAllWhenShown(true);
        menu.addMenuListener(m -> {
            for (LayerSpec l : scene.layers()) {
                m.add(layerMenu(l));
            }
            m.add(new Separator());
            MenuManager follow = new MenuManager("Follow");
            follow.add(action("None", IAction.AS_RADIO_BUTTON, scene.camera().followed() == null, () -> scene.camera().follow(null)));
            for (RobotState r : scene.world().robots()) {
                follow.add(action(r.id().address(), IAction.AS_RADIO_BUTTON, Objects.equals(r.id(), scene.camera().followed()),
                        () -> scene.camera().follow(r.id())));
            }
            m.add(follow);
            m.add(action("Centre on robots", IAction.AS_PUSH_BUTTON, false, this::centreOnRobots));
            m.add(new Separator());
            MenuManager source = new MenuManager("Source");
            for (BusSources.Source s : BusSources.all()) {
                source.add(action(s.label(), IAction.AS_RADIO_BUTTON, s.id().equals(sourceId), () -> followSource(s.id())));
            }
            m.add(source);
        });
        // the menu must exist before the first "about to show"
        menu.add(new Separator());
    }

    /**
     * The canvas's context menu: Break When, one robot data breakpoint per sensor shown now (its value now as the
     * threshold, to edit in the breakpoint's dialog), and the camera's actions.
     */
    private void installContextMenu() {
        MenuManager context = new MenuManager();
        context.setRemoveAllWhenShown(true);
        context.addMenuListener(m -> {
            MenuManager breakWhen = new MenuManager("Break When");
            for (String offer : breakWhenOffers()) {
                breakWhen.add(action(offer + "...", IAction.AS_PUSH_BUTTON, false,
                        () -> RobotDataBreakpointCommand.ask(offer, problem -> MessageDialog.openInformation(canvas.getShell(),
                                "Robot Data Breakpoint", problem))));
            }
            if (breakWhen.isEmpty()) {
                IAction none = action("(no sensor data shown)", IAction.AS_PUSH_BUTTON, false, () -> {
                });
                none.setEnabled(false);
                breakWhen.add(none);
            }
            m.add(breakWhen);
            m.add(new Separator());
            m.add(action("Centre on robots", IAction.AS_PUSH_BUTTON, false, this::centreOnRobots));
        });
        canvas.setMenu(context.createContextMenu(canvas));
    }

    /** The robot data breakpoints the context menu's Break When offers now: one per sensor the visible layers show. */
    public List<String> breakWhenOffers() {
        List<StreamMessage> shown = new ArrayList<>();
        for (LayerSpec l : scene.layers()) {
            if (l.visible()) {
                shown.addAll(scene.feed(l.id()).snapshot());
            }
        }
        return SensorConditions.offers(shown);
    }

    private MenuManager layerMenu(LayerSpec l) {
        MenuManager m = new MenuManager(l.name());
        m.add(action("Visible", IAction.AS_CHECK_BOX, l.visible(), () -> updateLayer(current(l).visible(!current(l).visible()))));
        m.add(action("Colour...", IAction.AS_PUSH_BUTTON, false, () -> {
            ColorDialog d = new ColorDialog(canvas.getShell());
            LayerSpec c = current(l);
            d.setRGB(new RGB((c.rgb() >> 16) & 0xFF, (c.rgb() >> 8) & 0xFF, c.rgb() & 0xFF));
            RGB rgb = d.open();
            if (rgb != null) {
                updateLayer(c.colour((rgb.red << 16) | (rgb.green << 8) | rgb.blue, c.alpha()));
            }
        }));
        MenuManager opacity = new MenuManager("Opacity");
        for (int pct : new int[] { 100, 75, 50, 30, 15 }) {
            opacity.add(action(pct + " %", IAction.AS_RADIO_BUTTON, Math.round(l.alpha() * 100) == pct,
                    () -> updateLayer(current(l).colour(current(l).rgb(), pct / 100.0))));
        }
        m.add(opacity);
        m.add(action("Draw later (on top)", IAction.AS_PUSH_BUTTON, false, () -> moveLayer(l, +1)));
        m.add(action("Draw earlier (below)", IAction.AS_PUSH_BUTTON, false, () -> moveLayer(l, -1)));
        return m;
    }

    /** Swaps the layer's draw order with its neighbour's. */
    private void moveLayer(LayerSpec l, int direction) {
        List<LayerSpec> layers = scene.layers();
        int i = layers.indexOf(current(l)), j = i + direction;
        if (i < 0 || j < 0 || j >= layers.size()) {
            return;
        }
        LayerSpec a = layers.get(i), b = layers.get(j);
        int oa = a.order(), ob = b.order();
        if (oa == ob) {
            ob = oa + direction;
        }
        updateLayer(a.order(ob));
        updateLayer(b.order(oa));
    }

    private LayerSpec current(LayerSpec l) {
        for (LayerSpec c : scene.layers()) {
            if (c.id().equals(l.id())) {
                return c;
            }
        }
        return l;
    }

    private void centreOnRobots() {
        List<RobotState> robots = scene.world().robots().stream().filter(RobotState::poseSeen).toList();
        if (robots.isEmpty()) {
            scene.camera().centreOn(0, 0);
        } else {
            double x = 0, y = 0;
            for (RobotState r : robots) {
                x += r.pose().x();
                y += r.pose().y();
            }
            scene.camera().follow(null);
            scene.camera().centreOn(x / robots.size(), y / robots.size());
        }
        redraw.request();
    }

    private Action action(String text, int style, boolean checked, Runnable run) {
        Action a = new Action(text, style) {
            @Override
            public void run() {
                run.run();
                redraw.request();
            }
        };
        a.setChecked(checked);
        return a;
    }
}
