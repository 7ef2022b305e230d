package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

import org.eclipse.e4.ui.model.application.ui.basic.MPart;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.XMLMemento;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.scene.LastMessages;
import org.stagecraft.scene.LayerSpec;
import org.stagecraft.scene.RobotId;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.scene.ViewSetup;
import org.stagecraft.spy.hold.HoldReason;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.HoldStreams;
import org.stagecraft.spy.proxy.NetworkSpy;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.views.FramePixels;
import org.stagecraft.views.RobotView;
import org.stagecraft.views.internal.ViewMemento;

/**
 * Two Robot Views on the workbench, fed from the recorded single-robot session played through a real
 * Network Spy (replay peers on both sides of real sockets, the spy's pipeline publishing on the workbench
 * bus): both draw the robot and its laser. Then one view's layer setup goes through its memento.
 *
 * <p>A real workbench restart is not possible inside one tycho-surefire run, so the restart is simulated
 * with the workbench's own persistence: closing the view makes the workbench call {@code saveState} and
 * keep the memento's XML in the part's model (the model is what it writes to workbench.xmi at shutdown
 * and reads at start); reopening it creates a new view instance that gets that memento in
 * {@code init(site, memento)}, exactly as after a restart. Only the writing and reading of workbench.xmi
 * itself is not exercised; the memento text is also read back on its own to show it is self-contained.
 *
 * <p>Runs on the UI thread: waits spin the display loop with deadlines (no sleeps); the socket peers
 * run on virtual threads and are awaited the same way, so no timeout thread is needed to end a hang.
 */
@Timeout(180)
class RobotViewWorkbenchTest {
    static final int LASER_HIT = 0x1A4DFF;
    static final int HELD_TEXT = 0xD90D0D; // the hold overlay's red (0.85, 0.05, 0.05)
    static final int ROBOT_HEADING = 0x670B0B; // the robots layer's colour (#E61A1A) at shade 0.45, opaque
    private final List<AutoCloseable> cleanup = new ArrayList<>();
    private final ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor();
    private IWorkbenchPage page;

    @BeforeEach
    void page() {
        page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
    }

    @AfterEach
    void close() throws Exception {
        for (int i = cleanup.size() - 1; i >= 0; i--) {
            cleanup.get(i).close();
        }
        peers.shutdownNow();
    }

    /** Plays the recorded session through a spy publishing on the workbench bus; returns the Player address. */
    private String replayThroughTheSpy() throws Exception {
        RecordedConnection rec = RecordedConnection.read(RecordedScene.trace("pioneer-laser-sonar.gt.trace.jsonl")).get(0);
        ServerSocket player = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        cleanup.add(player);
        ObservationPipeline pipeline = new ObservationPipeline(WorkbenchBus.get(), new PlayerDecoder(CodecRegistry.standard()),
                null, 64 << 20);
        NetworkSpy spy = new NetworkSpy(List.of(Route.loopback(0, "127.0.0.1", player.getLocalPort())), pipeline);
        spy.start();
        cleanup.add(pipeline);
        cleanup.add(spy);
        CompletableFuture<ReplayPeer.Result> server = CompletableFuture.supplyAsync(() -> {
            try (Socket s = player.accept()) {
                return ReplayPeer.serve(s, rec);
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, peers);
        CompletableFuture<ReplayPeer.Result> client = CompletableFuture.supplyAsync(() -> {
            try {
                Socket s = new Socket();
                s.connect(spy.boundAddresses().get(0));
                return ReplayPeer.client(s, rec);
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }, peers);
        GlHarness.spinUntil(() -> server.isDone() && client.isDone(), 60_000, "the replay through the spy");
        assertTrue(client.get().matches(), "the robot program got what Player sent, through the spy");
        assertTrue(server.get().matches(), "Player got what the robot program sent, through the spy");
        // the connection has ended and observation has published everything it queued (it publishes in rounds)
        GlHarness.spinUntil(() -> spy.openConnections() == 0, 30_000, "the spy to see the connection end");
        pipeline.close();
        assertTrue(pipeline.messages() > 3000, "the spy published the session: " + pipeline.messages());
        assertEquals(0, pipeline.decodeProblems());
        InetAddressString listen = new InetAddressString(spy.boundAddresses().get(0));
        return listen.text;
    }

    private record InetAddressString(String text) {
        InetAddressString(java.net.InetSocketAddress a) {
            this(a.getAddress().getHostAddress() + ":" + a.getPort());
        }
    }

    private RobotView show(String secondary) throws Exception {
        RobotView v = (RobotView) page.showView(RobotView.ID, secondary, IWorkbenchPage.VIEW_VISIBLE);
        assertNotNull(v);
        return v;
    }

    /**
     * Waits until the view has the robot and its laser, and has redrawn by itself (frames counted before
     * the data was sent) up to the newest laser data it received; then follows the robot and draws a frame.
     * The data may all have arrived and been drawn before this is called (observation publishes in rounds
     * while the replay runs), so "a frame after the data" is judged by the version drawn, not by a frame
     * counted here.
     */
    private FramePixels drawnWithData(RobotView v, RobotId robot, long framesBefore) {
        // this robot's laser data: the feed also keeps the last scan of an earlier test's robot (its streams were
        // released), which satisfied a plain "not empty" before this robot's scans had arrived
        GlHarness.spinUntil(() -> v.scene().world().robot(robot).poseSeen() && v.scene().feed("laser").snapshot().stream()
                .anyMatch(m -> RobotId.of(m.key()).equals(robot)), 30_000,
                "the view to receive this robot's pose and laser data");
        GlHarness.spinUntil(() -> v.frames() > framesBefore
                && v.scene().drawnVersion("laser") == v.scene().feed("laser").version(), 10_000,
                "the view to redraw by itself with the newest laser data");
        v.scene().camera().follow(robot);
        return v.capture();
    }

    @Test
    void twoViewsDrawTheRecordedSessionFedThroughTheSpy() throws Exception {
        page.resetPerspective();
        RobotView a = show(null); // the perspective's Robot View
        RobotView b = show("second");
        assertNotEquals(a, b);
        GlHarness.spinUntil(() -> a.frames() > 0 && b.frames() > 0, 10_000, "both views to draw their first frame");
        long framesA = a.frames(), framesB = b.frames();
        String playerAddress = replayThroughTheSpy();
        RobotId robot = new RobotId(playerAddress);

        for (RobotView v : List.of(a, b)) {
            FramePixels f = drawnWithData(v, robot, v == a ? framesA : framesB);
            assertTrue(f.width() > 50 && f.height() > 50, "the view is on screen: " + f.width() + " x " + f.height());
            assertTrue(f.count(LASER_HIT, 2) >= 10, v.getViewSite().getSecondaryId() + ": laser hits drawn: " + f.count(LASER_HIT, 2));
            assertTrue(f.count(ROBOT_HEADING, 3) >= 5, "robot drawn: " + f.count(ROBOT_HEADING, 3));
            assertEquals(16, v.scene().world().mount(new org.stagecraft.scene.DeviceAddress(robot, 62, 0)).elements().size(),
                    "the sonar geometry came off the wire");
        }
        // the context menu's Break When: a robot data breakpoint per sensor shown, its value now as the threshold
        org.stagecraft.player.msg.Laser.Scan scan = (org.stagecraft.player.msg.Laser.Scan) org.stagecraft.scene.Payloads.body(
                a.scene().feed("laser").snapshot().stream().filter(m -> RobotId.of(m.key()).equals(robot)).findFirst().orElseThrow());
        float nearest = Float.POSITIVE_INFINITY;
        for (float r : scan.ranges().toArray()) {
            nearest = Math.min(nearest, r);
        }
        String laserOffer = "laser:0 min(ranges) < " + java.math.BigDecimal.valueOf(nearest).setScale(2, java.math.RoundingMode.HALF_UP)
                .stripTrailingZeros().toPlainString();
        List<String> offers = a.breakWhenOffers();
        assertTrue(offers.contains(laserOffer), "Break When offers " + laserOffer + ": " + offers);
        assertTrue(offers.contains("position2d:0 stall == 1"), offers.toString());
        assertTrue(offers.stream().anyMatch(o -> o.startsWith("ranger:0 min(ranges) < ")), "the sonar ring (ranger:0): " + offers);
        // a view opened after the session knows its sensors: the geometry replies came long before it
        RobotView late = show("late");
        assertTrue(late.scene().world().robot(robot).poseSeen());
        assertEquals(16, late.scene().world().mount(new org.stagecraft.scene.DeviceAddress(robot, 62, 0)).elements().size());
        page.hideView(late);
        page.hideView(b);
    }

    /**
     * Issue 18/19: a view opened while the robot program is suspended (nothing new comes) shows the last
     * known state of the robot at once, and that its robots are held.
     */
    @Test
    void aViewOpenedWhileNothingArrivesShowsTheLastKnownStateAndTheHold() throws Exception {
        StreamBus bus = WorkbenchBus.get();
        SharedWorld.of(bus); // as the workbench's startup does (it may not have run yet when this test runs first)
        RobotId robot = new RobotId(replayThroughTheSpy()); // the session is over: no more data
        bus.publish(new StreamMessage(HoldStreams.STATE, System.nanoTime(),
                new HoldState(true, true, Map.of(HoldReason.SUSPENDED, 1), 0, 1)));
        try {
            LastMessages store = LastMessages.find(bus).orElseThrow(() -> new AssertionError("the workbench keeps last values"));
            GlHarness.spinUntil(() -> !store.matching(StreamPattern.exactly(HoldStreams.STATE)).isEmpty(), 10_000,
                    "the hold state to reach the workbench's last values");
            RobotView late = show("suspended");
            assertTrue(!late.scene().feed("laser").snapshot().isEmpty(), "the laser layer starts from the last scan");
            assertTrue(late.scene().world().robot(robot).poseSeen());
            assertEquals("HELD (suspended in the debugger)", late.holdText());
            GlHarness.spinUntil(() -> late.frames() > 0, 10_000, "the new view to draw its first frame");
            late.scene().camera().follow(robot);
            FramePixels f = late.capture();
            assertTrue(f.count(LASER_HIT, 2) >= 10, "the last laser scan is drawn: " + f.count(LASER_HIT, 2));
            assertTrue(f.count(HELD_TEXT, 3) >= 10, "the HELD text is drawn: " + f.count(HELD_TEXT, 3));

            bus.publish(new StreamMessage(HoldStreams.STATE, System.nanoTime(), new HoldState(true, false, Map.of(), 0, 1)));
            GlHarness.spinUntil(() -> late.holdText() == null, 10_000, "the view to see the release");
            assertEquals(0, late.capture().count(HELD_TEXT, 3), "released: no HELD text");
            page.hideView(late);
        } finally {
            // the workbench bus outlives this test: leave it released
            bus.publish(new StreamMessage(HoldStreams.STATE, System.nanoTime(), new HoldState(true, false, Map.of(), 0, 2)));
        }
    }

    /**
     * Issue 24, item 5: the next session's robot is in view when it starts, wherever the user left the camera,
     * and the earlier session's robot (its trail, its last scan) is gone from the view.
     */
    @Test
    void theNextSessionsRobotIsFramedAndTheEarlierSessionsIsForgotten() throws Exception {
        RobotView v = show("sessions");
        GlHarness.spinUntil(() -> v.frames() > 0, 10_000, "the view's first frame");
        RobotId first = new RobotId(replayThroughTheSpy());
        GlHarness.spinUntil(() -> v.scene().world().ended(first), 10_000, "the first session's robot to end with its connection");
        v.scene().camera().follow(null);
        v.scene().camera().centreOn(100, 100); // looking elsewhere, as after panning about
        RobotId second = new RobotId(replayThroughTheSpy());
        assertNotEquals(first, second, "each session's Player has its own port");
        GlHarness.spinUntil(() -> second.equals(v.scene().camera().followed()), 10_000,
                "the view to follow the next session's robot (follows " + v.scene().camera().followed() + ")");
        assertTrue(v.scene().world().robots().stream().noneMatch(r -> r.id().equals(first)),
                "the earlier session's robot and its trail are gone: " + v.scene().world().robots());
        v.requestRedraw();
        GlHarness.spinUntil(() -> v.scene().feed("laser").snapshot().stream().noneMatch(m -> RobotId.of(m.key()).equals(first)),
                10_000, "the earlier session's last scan to be dropped from the view");
        FramePixels f = v.capture();
        assertTrue(f.count(ROBOT_HEADING, 3) >= 5, "the robot is in view: " + f.count(ROBOT_HEADING, 3));
        page.hideView(v);
    }

    @Test
    void layerSetupSurvivesARestartThroughTheMemento() throws Exception {
        RobotView b = show("persisted");
        LayerSpec laser = b.setup().layers().stream().filter(l -> l.id().equals("laser")).findFirst().orElseThrow();
        LayerSpec sonar = b.setup().layers().stream().filter(l -> l.id().equals("sonar")).findFirst().orElseThrow();
        b.updateLayer(laser.colour(0x00AA00, 0.5).order(99));
        b.updateLayer(sonar.visible(false));
        b.scene().camera().setMetresPerPixel(0.01);
        b.scene().camera().follow(new RobotId("127.0.0.1:6665"));
        ViewSetup configured = b.setup();

        page.hideView(b); // the workbench calls saveState and keeps the memento in the part's model

        RobotView restarted = show("persisted");
        assertNotSame(b, restarted, "a new view instance");
        assertEquals(configured.layers(), restarted.setup().layers(), "layers restored by init(site, memento)");
        assertEquals(configured.camera(), restarted.setup().camera(), "camera restored");
        String kept = restarted.getSite().getService(MPart.class).getPersistedState().get("memento");
        assertNotNull(kept, "the memento is in the part's model (written to workbench.xmi at shutdown)");
        assertTrue(kept.contains("robotViewVersion"), kept);

        // the same text read back on its own, as a restarted workbench reads it from workbench.xmi
        List<String> problems = new ArrayList<>();
        ViewSetup read = ViewMemento.read(XMLMemento.createReadRoot(new StringReader(kept)), problems::add);
        assertTrue(problems.isEmpty(), problems.toString());
        assertEquals(configured.layers(), read.layers());
        assertEquals("laser", read.layers().get(read.layers().size() - 1).id(), "drawn last");

        // and it draws with the restored setup: green laser hits, no blue ones, no sonar cones
        GlHarness.spinUntil(() -> restarted.frames() > 0, 10_000, "the reopened view to draw its first frame");
        long framesBefore = restarted.frames();
        RobotId robot = new RobotId(replayThroughTheSpy());
        restarted.scene().camera().follow(null);
        FramePixels f = drawnWithData(restarted, robot, framesBefore);
        assertTrue(f.count(0x00AA00, 2) >= 10, "restored laser colour drawn: " + f.count(0x00AA00, 2));
        assertEquals(0, f.count(LASER_HIT, 2), "no pixel in the old laser colour");
        page.hideView(restarted);
    }
}
