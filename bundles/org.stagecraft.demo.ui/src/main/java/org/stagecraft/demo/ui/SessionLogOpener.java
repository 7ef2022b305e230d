package org.stagecraft.demo.ui;

import org.eclipse.core.resources.IFile;
import org.eclipse.ui.IEditorDescriptor;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;

/**
 * Opens the session's growing spy log in the Session Log editor when that editor is installed. It
 * comes from another plug-in (org.stagecraft.replay.ui), looked up by id at run time so the demo
 * works, minus this step, in a product without it.
 */
final class SessionLogOpener {
    static final String EDITOR_ID = "org.stagecraft.replay.ui.sessionLogEditor";

    private SessionLogOpener() {
    }

    /** @return what happened, for the status: "opened", "not installed" or the error */
    static String open(IWorkbenchPage page, IFile log) {
        IEditorDescriptor editor = PlatformUI.getWorkbench().getEditorRegistry().findEditor(EDITOR_ID);
        if (editor == null) {
            DemoLog.info("the Session Log editor (" + EDITOR_ID + ") is not installed; not opening " + log.getFullPath());
            return "not installed";
        }
        try {
            IDE.openEditor(page, log, EDITOR_ID, true);
            DemoLog.info("opened " + log.getFullPath() + " in the Session Log editor");
            return "opened";
        } catch (PartInitException e) {
            DemoLog.error("cannot open " + log.getFullPath() + " in the Session Log editor: " + e.getMessage(), e);
            return "failed: " + e.getMessage();
        }
    }
}
