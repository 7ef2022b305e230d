package org.stagecraft.views;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.ToIntFunction;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.scene.BreakReading;
import org.stagecraft.scene.Camera;
import org.stagecraft.scene.LayerFeed;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.LayerStack;
import org.stagecraft.scene.SceneFeed;
import org.stagecraft.scene.WorldModel;
import org.stagecraft.scene.shapes.FloatList;
import org.stagecraft.scene.shapes.GridShape;
import org.stagecraft.scene.shapes.ReadingMark;
import org.stagecraft.streams.StreamBus;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2;
import com.jogamp.opengl.fixedfunc.GLMatrixFunc;
import com.jogamp.opengl.util.gl2.GLUT;

/**
 * Everything one Robot View draws, independent of the widget: the world model, the camera, the layers
 * (each a renderer with its feed) and the frame itself. The view, the pixel tests and the benchmark all
 * draw through {@link #render}.
 */
public final class RobotScene implements AutoCloseable {
    /** Background grey and grid shades. */
    public static final float BACKGROUND = 0.92f, MINOR_GRID = 0.84f, MAJOR_GRID = 0.70f;

    private volatile WorldModel world;
    private final Camera camera;
    private final LayerStack layers = new LayerStack(List.of());
    private final Map<String, StreamRenderer> renderers = new ConcurrentHashMap<>();
    private final Map<String, LayerFeed> feeds = new ConcurrentHashMap<>();
    private final List<StreamRenderer> retired = new ArrayList<>();
    private final Runnable onChange;
    private @Nullable StreamBus bus;
    private @Nullable SceneFeed sceneFeed;
    private boolean grid = true;
    private final FloatList minor = new FloatList(), major = new FloatList();
    private @Nullable GLUT glut;
    private long frames;
    /** Per layer, the feed version the last frame drew (read before its snapshot, so never ahead of it). */
    private final Map<String, Long> drawnVersions = new ConcurrentHashMap<>();
    /** Text drawn over everything (e.g. "HELD (suspended in the debugger)"), or null. */
    private volatile @Nullable String overlay;
    /** The reading a robot data breakpoint stopped on, marked over the layers, or null. */
    private volatile @Nullable BreakReading mark;
    /** The world's {@link WorldModel#forgetting()} the layers were last pruned at. */
    private long forgettingSeen;
    private final FloatList markLines = new FloatList(), markPoints = new FloatList();
    /** The mark's colour (0xFFD400) and its edge's. */
    public static final float[] MARK = { 1f, 212 / 255f, 0f }, MARK_EDGE = { 0f, 0f, 0f };

    /** @param onChange told (on bus threads) whenever new data arrived: the view schedules a redraw */
    public RobotScene(WorldModel world, Camera camera, Runnable onChange) {
        this.world = world;
        this.camera = camera;
        this.onChange = onChange;
    }

    public WorldModel world() {
        return world;
    }

    public Camera camera() {
        return camera;
    }

    /** Starts (or moves) the scene's subscriptions to {@code newBus}, its world model fed by the scene itself. */
    public synchronized void connect(StreamBus newBus) {
        connect(newBus, true);
    }

    /**
     * As {@link #connect(StreamBus)}; with {@code feedWorld} false only the layers subscribe, for a scene
     * whose world model is fed by someone else (a {@link org.stagecraft.scene.SharedWorld}).
     */
    public synchronized void connect(StreamBus newBus, boolean feedWorld) {
        disconnect();
        bus = newBus;
        if (feedWorld) {
            sceneFeed = new SceneFeed(newBus, world, onChange);
        }
        for (LayerSpec l : layers.inDrawOrder()) {
            feeds.get(l.id()).subscribe(newBus, l.pattern(), renderers.get(l.id()).deliveryPolicy());
        }
    }

    /**
     * Moves the layers to {@code newBus}, whose world model {@code newWorld} someone else feeds (the bus's
     * {@link org.stagecraft.scene.SharedWorld}): a view that changes the source it follows.
     */
    public synchronized void reconnect(StreamBus newBus, WorldModel newWorld) {
        disconnect();
        world = newWorld;
        connect(newBus, false);
    }

    public synchronized void disconnect() {
        if (sceneFeed != null) {
            sceneFeed.close();
            sceneFeed = null;
        }
        feeds.values().forEach(LayerFeed::close);
        bus = null;
    }

    /** Adds a layer (or replaces the one with its id, renderer and all). */
    public synchronized void addLayer(LayerSpec spec, StreamRenderer renderer) {
        removeLayer(spec.id());
        LayerFeed feed = new LayerFeed(onChange);
        renderers.put(spec.id(), renderer);
        feeds.put(spec.id(), feed);
        layers.put(spec);
        StreamBus bus = this.bus;
        if (bus != null) {
            feed.subscribe(bus, spec.pattern(), renderer.deliveryPolicy());
        }
    }

    public synchronized void removeLayer(String id) {
        @Nullable LayerFeed f = feeds.remove(id);
        if (f != null) {
            f.close();
        }
        @Nullable StreamRenderer r = renderers.remove(id);
        if (r != null) {
            retired.add(r); // its GPU data is freed at the next frame, when a context is current
        }
        layers.remove(id);
    }

    /** Changes a layer's look, order or pattern (a new pattern resubscribes it). */
    public synchronized void updateLayer(LayerSpec spec) {
        LayerSpec old = layers.get(spec.id());
        if (old == null) {
            throw new IllegalArgumentException("no layer '" + spec.id() + "'");
        }
        if (!old.rendererId().equals(spec.rendererId())) {
            throw new IllegalArgumentException("layer '" + spec.id() + "' keeps its renderer " + old.rendererId());
        }
        layers.put(spec);
        StreamBus bus = this.bus;
        if (bus != null && !old.pattern().equals(spec.pattern())) {
            feeds.get(spec.id()).subscribe(bus, spec.pattern(), renderers.get(spec.id()).deliveryPolicy());
        }
        onChange.run();
    }

    public List<LayerSpec> layers() {
        return layers.inDrawOrder();
    }

    public StreamRenderer renderer(String layerId) {
        return renderers.get(layerId);
    }

    public LayerFeed feed(String layerId) {
        return feeds.get(layerId);
    }

    /** Text to draw over the robots, top left, in red (null: none); e.g. the robot hold's state. */
    public void overlay(@Nullable String text) {
        overlay = text;
    }

    public @Nullable String overlay() {
        return overlay;
    }

    /** Marks the reading a robot data breakpoint stopped on ({@link ReadingMark}), or nothing (null). */
    public void mark(@Nullable BreakReading reading) {
        mark = reading;
    }

    public @Nullable BreakReading mark() {
        return mark;
    }

    public void showGrid(boolean show) {
        grid = show;
    }

    /** Frames rendered so far. */
    public long frames() {
        return frames;
    }

    /**
     * The version of the layer's feed that the last frame drew (everything up to it, maybe more), or -1
     * if no frame has drawn the layer: equal to {@code feed(layerId).version()} once the newest data is
     * on screen.
     */
    public long drawnVersion(String layerId) {
        return drawnVersions.getOrDefault(layerId, -1L);
    }

    /** Draws one frame into the current GL context's {@code width} x {@code height} viewport. */
    public void render(GL2 gl, int width, int height) {
        List<StreamRenderer> dead;
        synchronized (this) {
            dead = new ArrayList<>(retired);
            retired.clear();
        }
        dead.forEach(r -> r.disposeGl(gl));

        long forgetting = world.forgetting();
        if (forgetting != forgettingSeen) {
            forgettingSeen = forgetting;
            // a new session's robots came: the last data of the robots the world forgot is an earlier session's
            WorldModel w = world;
            feeds.values().forEach(f -> f.forget(k -> w.forgotten(org.stagecraft.scene.RobotId.of(k))));
        }
        camera.viewport(width, height);
        camera.track(world);
        gl.glViewport(0, 0, width, height);
        gl.glClearColor(BACKGROUND, BACKGROUND, BACKGROUND, 1);
        gl.glClear(GL.GL_COLOR_BUFFER_BIT);
        gl.glMatrixMode(GLMatrixFunc.GL_PROJECTION);
        gl.glLoadIdentity();
        gl.glOrtho(camera.left(), camera.right(), camera.bottom(), camera.top(), -1, 1);
        gl.glMatrixMode(GLMatrixFunc.GL_MODELVIEW);
        gl.glLoadIdentity();
        gl.glDisable(GL.GL_DEPTH_TEST);
        gl.glEnable(GL.GL_BLEND);
        gl.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA);

        if (grid) {
            drawGrid(gl);
        }
        for (LayerSpec l : layers.inDrawOrder()) {
            @Nullable StreamRenderer r = renderers.get(l.id());
            @Nullable LayerFeed f = feeds.get(l.id());
            if (!l.visible() || r == null || f == null) {
                continue;
            }
            // the version first: a message arriving during the snapshot makes it look newer than the version,
            // which schedules another frame, never older (a renderer caching by version would keep stale data)
            long version = f.version();
            r.frame(gl, new RenderInput(l, f.snapshot(), f.drainUnseen(), version, world, camera));
            drawnVersions.put(l.id(), version);
        }
        drawMark(gl);
        drawOverlay(gl, width, height);
        frames++;
    }

    private void drawGrid(GL2 gl) {
        double spacing = GridShape.spacing(camera);
        minor.clear();
        major.clear();
        GridShape.lines(camera, spacing, minor, major);
        gl.glLineWidth(1);
        lines(gl, minor, MINOR_GRID);
        lines(gl, major, MAJOR_GRID);
        // metres along the bottom and left edges, at the major lines
        if (glut == null) {
            glut = new GLUT();
        }
        gl.glColor4f(0.35f, 0.35f, 0.35f, 1);
        double step = spacing * 5;
        for (double x = Math.ceil(camera.left() / step) * step; x <= camera.right(); x += step) {
            gl.glWindowPos2d(camera.worldToWindowX(x) + 3, 3);
            glut.glutBitmapString(GLUT.BITMAP_HELVETICA_10, label(x));
        }
        for (double y = Math.ceil(camera.bottom() / step) * step; y <= camera.top(); y += step) {
            gl.glWindowPos2d(3, camera.worldToWindowY(y) + 3);
            glut.glutBitmapString(GLUT.BITMAP_HELVETICA_10, label(y));
        }
    }

    /** The mark, yellow on a black edge: it reads over every layer's colour (the robots are red, the laser blue). */
    private void drawMark(GL2 gl) {
        BreakReading reading = mark;
        if (reading == null) {
            return;
        }
        markLines.clear();
        markPoints.clear();
        ReadingMark.build(reading, world, camera.metresPerPixel(), markLines, markPoints);
        markPass(gl, MARK_EDGE, 6, 12);
        markPass(gl, MARK, 3, 8);
        gl.glLineWidth(1);
        gl.glPointSize(1);
    }

    private void markPass(GL2 gl, float[] rgb, float lineWidth, float pointSize) {
        gl.glColor4f(rgb[0], rgb[1], rgb[2], 1);
        gl.glLineWidth(lineWidth);
        vertices(gl, GL.GL_LINES, markLines);
        gl.glPointSize(pointSize);
        vertices(gl, GL.GL_POINTS, markPoints);
    }

    /**
     * The overlay on a white band, so it reads over any layer; wrapped at spaces into lines that fit
     * the view's width (a narrow view cut "HELD (suspended in the debugger)" off at its edge).
     */
    private void drawOverlay(GL2 gl, int width, int height) {
        String text = overlay;
        if (text == null) {
            return;
        }
        if (glut == null) {
            glut = new GLUT();
        }
        GLUT g = glut;
        List<String> lines = wrap(text, width - 2 * OVERLAY_MARGIN, s -> g.glutBitmapLength(GLUT.BITMAP_HELVETICA_18, s));
        int w = 0;
        for (String line : lines) {
            w = Math.max(w, g.glutBitmapLength(GLUT.BITMAP_HELVETICA_18, line));
        }
        double mpp = camera.metresPerPixel();
        double x0 = camera.left(), y1 = camera.top();
        int bandHeight = 8 + OVERLAY_LINE * lines.size();
        gl.glColor4f(1, 1, 1, 0.85f);
        gl.glBegin(GL2.GL_QUADS);
        gl.glVertex2d(x0, y1);
        gl.glVertex2d(x0 + (w + 2 * OVERLAY_MARGIN) * mpp, y1);
        gl.glVertex2d(x0 + (w + 2 * OVERLAY_MARGIN) * mpp, y1 - bandHeight * mpp);
        gl.glVertex2d(x0, y1 - bandHeight * mpp);
        gl.glEnd();
        gl.glColor4f(0.85f, 0.05f, 0.05f, 1);
        for (int i = 0; i < lines.size(); i++) {
            gl.glWindowPos2d(OVERLAY_MARGIN, height - OVERLAY_LINE * (i + 1));
            g.glutBitmapString(GLUT.BITMAP_HELVETICA_18, lines.get(i));
        }
    }

    /** Space left and right of the overlay's text, in pixels. */
    private static final int OVERLAY_MARGIN = 8;
    /** The overlay's line height, in pixels (Helvetica 18). */
    private static final int OVERLAY_LINE = 22;

    /**
     * {@code text} in lines no wider than {@code maxWidth} (as {@code width} measures), broken at
     * spaces; a word wider than that alone is a line of its own.
     */
    static List<String> wrap(String text, int maxWidth, ToIntFunction<String> width) {
        List<String> lines = new ArrayList<>();
        StringBuilder line = new StringBuilder();
        for (String word : text.split(" ")) {
            String candidate = line.isEmpty() ? word : line + " " + word;
            if (line.isEmpty() || width.applyAsInt(candidate) <= maxWidth) {
                line.setLength(0);
                line.append(candidate);
            } else {
                lines.add(line.toString());
                line.setLength(0);
                line.append(word);
            }
        }
        lines.add(line.toString());
        return lines;
    }

    private static String label(double metres) {
        double r = Math.abs(metres) < 1e-9 ? 0 : metres;
        return (r == Math.rint(r) ? Long.toString((long) r) : String.format("%.1f", r)) + " m";
    }

    private static void lines(GL2 gl, FloatList v, float grey) {
        gl.glColor4f(grey, grey, grey, 1);
        vertices(gl, GL.GL_LINES, v);
    }

    /** Draws {@code v}'s (x, y) pairs as {@code mode} (immediate mode: the grid and the mark are a few hundred vertices). */
    private static void vertices(GL2 gl, int mode, FloatList v) {
        gl.glBegin(mode);
        float[] a = v.array();
        for (int i = 0; i < v.size(); i += 2) {
            gl.glVertex2f(a[i], a[i + 1]);
        }
        gl.glEnd();
    }

    /** Frees every renderer's GPU data; the GL context must be current. */
    public synchronized void disposeGl(GL2 gl) {
        renderers.values().forEach(r -> r.disposeGl(gl));
        retired.forEach(r -> r.disposeGl(gl));
        retired.clear();
    }

    @Override
    public void close() {
        disconnect();
    }
}
