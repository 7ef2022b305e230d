package org.stagecraft.demo.ui;

import java.util.List;
import java.util.Map;

import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IViewPart;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.WorkbenchException;
import org.stagecraft.scene.DefaultLayers;
import org.stagecraft.scene.ViewSetup;
import org.stagecraft.tools.ui.view.ToolsView;
import org.stagecraft.views.RobotView;

/**
 * The demo's views (UI thread): the Stagecraft perspective with its Robot View close on the robot,
 * a second Robot View farther out (trail and sensors in the cave), and the Tools view with the
 * session's parts.
 */
final class DemoViews {
    static final String PERSPECTIVE = "org.stagecraft.ui.perspective";
    static final String OVERVIEW = "demo-overview";
    /** Metres per pixel of the overview: the 16 m cave in about 400 pixels. */
    private static final String OVERVIEW_SCALE = "0.04";

    private DemoViews() {
    }

    static List<RobotView> open(IWorkbenchWindow window) throws PartInitException, WorkbenchException {
        // the views are the demo: give them the screen (bounds too, for a display without a window manager)
        window.getShell().setBounds(window.getShell().getDisplay().getPrimaryMonitor().getClientArea());
        window.getShell().setMaximized(true);
        PlatformUI.getWorkbench().showPerspective(PERSPECTIVE, window);
        IWorkbenchPage page = window.getActivePage();
        IViewPart outline = page.findView(IPageLayout.ID_OUTLINE);
        if (outline != null) {
            page.hideView(outline); // nothing to outline here; the Debug view below it shows the session
        }
        page.showView(ToolsView.ID, null, IWorkbenchPage.VIEW_VISIBLE);
        RobotView near = (RobotView) page.showView(RobotView.ID);
        RobotView overview = (RobotView) page.showView(RobotView.ID, OVERVIEW, IWorkbenchPage.VIEW_VISIBLE);
        // default layers (laser, sonar, robots with their trail), zoomed out
        overview.applySetup(new ViewSetup(DefaultLayers.create(), Map.of("centreX", "0", "centreY", "0",
                "metresPerPixel", OVERVIEW_SCALE)));
        return List.of(near, overview);
    }
}
