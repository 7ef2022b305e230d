package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;

import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.debug.ui.DebugUITools;
import org.eclipse.debug.ui.IDebugUIConstants;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.internal.WorkbenchPage;
import org.eclipse.ui.internal.registry.IActionSetDescriptor;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.stagecraft.tests.support.Await;
import org.stagecraft.tools.ui.launch.LaunchAttributes;

/**
 * Issue 24, items 3 and 11: debugging a Robot Session in the product asks no "Confirm Perspective
 * Switch" at every suspension, the perspective it debugs in has the views a user needs, and the Run
 * menu has Toggle Breakpoint (Ctrl+Shift+B).
 */
class DebuggingLayoutTest {
    private static final String STAGECRAFT = "org.stagecraft.ui.perspective";
    private static final String TOOLS_VIEW = "org.stagecraft.tools.ui.toolsView";
    private static final String BREAKPOINT_ACTIONS = "org.eclipse.debug.ui.breakpointActionSet";

    /** Shows a perspective in the workbench window (on the UI thread: these tests run off it). */
    private static IWorkbenchPage show(String perspective) {
        return Await.ui(() -> {
            IWorkbenchWindow window = PlatformUI.getWorkbench().getWorkbenchWindows()[0];
            return PlatformUI.getWorkbench().showPerspective(perspective, window);
        });
    }

    @AfterEach
    void backToStagecraft() {
        show(STAGECRAFT);
    }

    /**
     * A suspension switches to the perspective the launch's type names for its mode, after asking when
     * it is not the one shown: naming the Stagecraft perspective means no question while debugging in it.
     */
    @Test
    void aSuspendedRobotSessionStaysInTheStagecraftPerspective() {
        ILaunchConfigurationType type = DebugPlugin.getDefault().getLaunchManager()
                .getLaunchConfigurationType(LaunchAttributes.TYPE);
        assertEquals(STAGECRAFT, DebugUITools.getLaunchPerspective(type, ILaunchManager.DEBUG_MODE));
    }

    @Test
    void theStagecraftPerspectiveHasTheDebugViewsAndToggleBreakpoint() {
        IWorkbenchPage page = show(STAGECRAFT);
        for (String view : List.of(IDebugUIConstants.ID_DEBUG_VIEW, IDebugUIConstants.ID_VARIABLE_VIEW,
                IDebugUIConstants.ID_BREAKPOINT_VIEW, TOOLS_VIEW)) {
            assertNotNull(Await.ui(() -> page.findViewReference(view)), view + " in the Stagecraft perspective");
        }
        List<String> actionSets = Await.ui(() -> actionSets(page));
        assertTrue(actionSets.contains(BREAKPOINT_ACTIONS),
                "Run > Toggle Breakpoint (Ctrl+Shift+B) comes with the breakpoint action set: " + actionSets);
    }

    @Test
    void theDebugPerspectiveHasTheToolsView() {
        IWorkbenchPage page = show(IDebugUIConstants.ID_DEBUG_PERSPECTIVE);
        assertNotNull(Await.ui(() -> page.findViewReference(TOOLS_VIEW)),
                "the Tools view (HELD, the session's parts) while debugging");
    }

    /** The action sets the page shows (no API tells them: the workbench's own page does). */
    @SuppressWarnings("restriction")
    private static List<String> actionSets(IWorkbenchPage page) {
        return Arrays.stream(((WorkbenchPage) page).getActionSets()).map(IActionSetDescriptor::getId).toList();
    }
}
