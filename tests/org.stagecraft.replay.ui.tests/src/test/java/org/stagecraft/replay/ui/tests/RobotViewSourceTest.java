package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.core.streams.BusSources;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.scene.RobotId;
import org.stagecraft.scene.RobotState;
import org.stagecraft.scene.SharedWorld;
import org.stagecraft.scene.WorldModel;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.views.RobotView;

/**
 * "A view can follow live or a chosen log": a Robot View opened from the editor follows its replay and
 * sees the recorded robot move; the choice survives the view's memento; when the log closes the view
 * goes back to Live, and comes back to the log when it is opened again.
 */
@Timeout(180)
class RobotViewSourceTest {
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
    void aRobotViewFollowingTheLogSeesTheReplayedRobot() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.spyLog("follow.mcap", 64 << 10));
        RobotView view = e.showInRobotView();
        assertEquals(e.sourceId(), view.sourceId());
        assertSame(e.bus(), view.bus(), "the view follows the editor's bus");
        Ui.spinUntil(() -> view.frames() > 0, 10_000, "the view's first frame");
        long framesBefore = view.frames();
        RobotId robot = new RobotId(TestLogs.PORT_LISTEN);
        assertTrue(!view.scene().world().robot(robot).poseSeen(), "nothing replayed yet");

        // the poses the view's world takes, seen as they come: at 16x the replay can be over before this
        // thread looks, so "moved" is judged from what was seen, not against a pose read afterwards
        WorldModel world = SharedWorld.of(e.bus()).world();
        assertSame(world, view.scene().world(), "the view draws the editor's world");
        Set<Object> poses = ConcurrentHashMap.newKeySet();
        try (AutoCloseable seeing = SharedWorld.of(e.bus()).listen(() -> {
            RobotState r = world.robot(robot);
            if (r.poseSeen()) {
                poses.add(r.pose());
            }
        })) {
            e.replayer().setSpeed(16);
            e.replayer().play();
            Ui.spinUntil(() -> view.scene().world().robot(robot).poseSeen() && !view.scene().feed("laser").snapshot().isEmpty(),
                    30_000, "the replayed robot and its laser in the view");
            Ui.spinUntil(() -> view.frames() > framesBefore, 10_000, "the view to redraw with the replayed data");
            Ui.spinUntil(() -> view.scene().world().mount(new org.stagecraft.scene.DeviceAddress(robot, 62, 0)).elements().size() == 16,
                    10_000, "the sonar geometry (16 transducers) from the log's GET_GEOM reply");
            Ui.spinUntil(() -> poses.size() >= 2, 30_000, "the robot to move");
        }
        e.replayer().pause();
        assertTrue(WorkbenchBus.get() != e.bus());

        // the choice persists through the memento (closing and reopening the view is what a restart does)
        String secondary = view.getViewSite().getSecondaryId();
        page.hideView(view);
        RobotView again = (RobotView) page.showView(RobotView.ID, secondary, IWorkbenchPage.VIEW_VISIBLE);
        assertNotSame(view, again);
        assertEquals(e.sourceId(), again.sourceId(), "restored from the memento");
        assertSame(e.bus(), again.bus());

        // the log closes: back to Live, still remembering the log
        String source = e.sourceId();
        page.closeEditor(e, false);
        Ui.spinUntil(() -> again.bus() == WorkbenchBus.get(), 5_000, "the view to fall back to Live");
        assertEquals(source, again.sourceId());
        assertTrue(again.getContentDescription().contains("is not open; showing Live"), again.getContentDescription());

        // opened again (same file, same id): the view follows it again by itself
        SessionLogEditor reopened = SessionLogEditorTest.open(page, TestLogs.project().getFile("follow.mcap"));
        assertEquals(source, reopened.sourceId());
        Ui.spinUntil(() -> again.bus() == reopened.bus(), 5_000, "the view to follow the reopened log");
        again.followSource(BusSources.LIVE);
        assertSame(WorkbenchBus.get(), again.bus());
        assertEquals("", again.getContentDescription());
        page.hideView(again);
    }
}
