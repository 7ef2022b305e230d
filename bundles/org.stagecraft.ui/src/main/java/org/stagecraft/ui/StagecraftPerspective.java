package org.stagecraft.ui;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.ui.IFolderLayout;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IPerspectiveFactory;
import org.eclipse.ui.console.IConsoleConstants;

/**
 * The Stagecraft perspective: editor area in the middle, Project Explorer on the left,
 * Console and Problems at the bottom, the Robot View on the right of the editor with Outline beside it;
 * further Robot Views (Window ▸ New Robot View) open below the first.
 */
public class StagecraftPerspective implements IPerspectiveFactory {

    /** Id of the perspective (plugin.xml, plugin_customization.ini). */
    public static final String ID = "org.stagecraft.ui.perspective";
    /** The Robot View (org.stagecraft.views); by id, so that this bundle does not depend on the GL one. */
    public static final String ROBOT_VIEW_ID = "org.stagecraft.views.robot";

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createInitialLayout(IPageLayout layout) {
        String editorArea = layout.getEditorArea();
        layout.setEditorAreaVisible(true);

        IFolderLayout left = layout.createFolder("org.stagecraft.ui.left", IPageLayout.LEFT, 0.22f, editorArea);
        left.addView(IPageLayout.ID_PROJECT_EXPLORER);

        IFolderLayout bottom = layout.createFolder("org.stagecraft.ui.bottom", IPageLayout.BOTTOM, 0.70f, editorArea);
        bottom.addView(IConsoleConstants.ID_CONSOLE_VIEW);
        bottom.addView(IPageLayout.ID_PROBLEM_VIEW);

        IFolderLayout robot = layout.createFolder("org.stagecraft.ui.robot", IPageLayout.RIGHT, 0.45f, editorArea);
        robot.addView(ROBOT_VIEW_ID);
        IFolderLayout moreRobots = layout.createFolder("org.stagecraft.ui.robots", IPageLayout.BOTTOM, 0.5f,
                "org.stagecraft.ui.robot");
        moreRobots.addPlaceholder(ROBOT_VIEW_ID + ":*");

        IFolderLayout right = layout.createFolder("org.stagecraft.ui.right", IPageLayout.RIGHT, 0.75f, "org.stagecraft.ui.robot");
        right.addView(IPageLayout.ID_OUTLINE);

        layout.addShowViewShortcut(IPageLayout.ID_PROJECT_EXPLORER);
        layout.addShowViewShortcut(IConsoleConstants.ID_CONSOLE_VIEW);
        layout.addShowViewShortcut(IPageLayout.ID_PROBLEM_VIEW);
        layout.addShowViewShortcut(IPageLayout.ID_OUTLINE);
        layout.addShowViewShortcut(ROBOT_VIEW_ID);
        layout.addPerspectiveShortcut(ID);
    }
}
