package org.stagecraft.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IPerspectiveDescriptor;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.Test;

/** Runs inside the Stagecraft product's workbench (tycho-surefire, UI harness, UI thread). */
class StagecraftPerspectiveTest {

    private static final String PERSPECTIVE_ID = "org.stagecraft.ui.perspective";
    private static final String CONSOLE_VIEW_ID = "org.eclipse.ui.console.ConsoleView";

    @Test
    void perspectiveIsRegistered() {
        IPerspectiveDescriptor descriptor = PlatformUI.getWorkbench().getPerspectiveRegistry()
                .findPerspectiveWithId(PERSPECTIVE_ID);
        assertNotNull(descriptor, "perspective " + PERSPECTIVE_ID + " is not registered");
        assertEquals("Stagecraft", descriptor.getLabel());
    }

    @Test
    void perspectiveIsTheProductDefault() {
        // set by the product's plugin_customization.ini
        assertEquals(PERSPECTIVE_ID, PlatformUI.getWorkbench().getPerspectiveRegistry().getDefaultPerspective());
    }

    @Test
    void perspectiveCanBeShownWithItsViews() throws Exception {
        IWorkbench workbench = PlatformUI.getWorkbench();
        IWorkbenchWindow window = workbench.getActiveWorkbenchWindow();
        assertNotNull(window, "no active workbench window");

        IWorkbenchPage page = workbench.showPerspective(PERSPECTIVE_ID, window);

        assertEquals(PERSPECTIVE_ID, page.getPerspective().getId());
        assertEquals(PERSPECTIVE_ID, window.getActivePage().getPerspective().getId());
        for (String viewId : new String[] { IPageLayout.ID_PROJECT_EXPLORER, CONSOLE_VIEW_ID,
                IPageLayout.ID_PROBLEM_VIEW, IPageLayout.ID_OUTLINE }) {
            assertNotNull(page.findViewReference(viewId), "view " + viewId + " is not in the Stagecraft perspective");
        }
    }
}
