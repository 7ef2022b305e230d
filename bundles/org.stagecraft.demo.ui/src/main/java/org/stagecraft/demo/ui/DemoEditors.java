package org.stagecraft.demo.ui;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.ide.IDE;
import org.osgi.service.prefs.BackingStoreException;
import org.stagecraft.tools.ui.view.ToolsView;

/**
 * The rest of the demo's screen once the session runs (UI thread): the Player cfg in the editor area
 * (what the session runs), the Session Log on top of it when that editor is installed, and the Tools
 * view in front of the consoles.
 */
final class DemoEditors {
    /** Text editor of the platform: a .cfg has no editor of its own. */
    private static final String TEXT_EDITOR = "org.eclipse.ui.DefaultTextEditor";

    private DemoEditors() {
    }

    /** @return what happened to the Session Log, for the status */
    static String open(IWorkbenchPage page, IFile cfg, @Nullable IFile spyLog) {
        try {
            IDE.openEditor(page, cfg, TEXT_EDITOR, false);
        } catch (PartInitException e) {
            DemoLog.warn("cannot show " + cfg.getFullPath() + ": " + e.getMessage());
        }
        String sessionLog = spyLog == null ? "no spy log" : SessionLogOpener.open(page, spyLog);
        try {
            page.showView(ToolsView.ID, null, IWorkbenchPage.VIEW_VISIBLE);
        } catch (PartInitException e) {
            DemoLog.warn("cannot show the Tools view: " + e.getMessage());
        }
        return sessionLog;
    }

    /**
     * The consoles would come to the front at every line the tools print, hiding the Tools view
     * stacked with them; in the demo workspace they stay behind (Window > Preferences > Run/Debug >
     * Console turns it back on).
     */
    static void keepConsolesBehind() {
        IEclipsePreferences debugUi = InstanceScope.INSTANCE.getNode("org.eclipse.debug.ui");
        debugUi.putBoolean("DEBUG.consoleOpenOnOut", false);
        debugUi.putBoolean("DEBUG.consoleOpenOnErr", false);
        try {
            debugUi.flush();
        } catch (BackingStoreException e) {
            DemoLog.warn("cannot store the console preferences: " + e.getMessage());
        }
    }
}
