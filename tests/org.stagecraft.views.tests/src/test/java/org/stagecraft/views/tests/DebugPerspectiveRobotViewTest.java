package org.stagecraft.views.tests;

import static org.junit.jupiter.api.Assertions.assertNotNull;

import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.views.RobotView;

/** Issue 24, item 3: debugging in Eclipse's Debug perspective keeps the robots (and a hold's HELD) in sight. */
class DebugPerspectiveRobotViewTest {
    /** Eclipse's Debug perspective (org.eclipse.debug.ui's IDebugUIConstants.ID_DEBUG_PERSPECTIVE). */
    private static final String DEBUG_PERSPECTIVE = "org.eclipse.debug.ui.DebugPerspective";

    private final IWorkbenchWindow window = PlatformUI.getWorkbench().getActiveWorkbenchWindow();

    @AfterEach
    void backToTheDefault() throws Exception {
        PlatformUI.getWorkbench().showPerspective(
                PlatformUI.getWorkbench().getPerspectiveRegistry().getDefaultPerspective(), window);
    }

    @Test
    void theDebugPerspectiveShowsARobotView() throws Exception {
        assertNotNull(PlatformUI.getWorkbench().getPerspectiveRegistry().findPerspectiveWithId(DEBUG_PERSPECTIVE),
                "the Debug perspective is in the test's workbench");
        IWorkbenchPage page = PlatformUI.getWorkbench().showPerspective(DEBUG_PERSPECTIVE, window);
        assertNotNull(page.findViewReference(RobotView.ID), "a Robot View in the Debug perspective");
        // views of one id are one part shared by the perspectives that place it (E4): the Stagecraft
        // perspective's Robot View is the one shown here, not a second one on the bus
        assertNotNull(page.findView(RobotView.ID), "shown, not only placed");
    }
}
