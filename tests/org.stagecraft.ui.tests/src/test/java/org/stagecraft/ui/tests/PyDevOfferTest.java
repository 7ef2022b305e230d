package org.stagecraft.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;

import org.eclipse.core.commands.Command;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.jface.notifications.NotificationPopup;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.editors.text.TextEditor;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.Test;
import org.stagecraft.pydev.ui.PyDev;
import org.stagecraft.pydev.ui.PyDevOffer;

/** Stagecraft without PyDev: .py files open as text, the product offers PyDev through p2's installer. */
class PyDevOfferTest {

    @Test
    void withoutPyDevAFirstStartNotificationOffersToInstallIt() {
        assertFalse(PyDev.installed(), "this runtime has no PyDev");
        Display display = Display.getCurrent();
        long deadline = System.nanoTime() + 60_000_000_000L;
        // the offer comes from the workbench's early startup, then the UI thread: run the event loop until it shows
        while (PyDevOffer.lastShown() == null) {
            assertTrue(System.nanoTime() < deadline, "no PyDev offer within 60 s of the start");
            display.timerExec(50, () -> { });
            if (!display.readAndDispatch()) {
                display.sleep();
            }
        }
        NotificationPopup popup = PyDevOffer.lastShown();
        assertNotNull(popup.getShell());
        assertTrue(InstanceScope.INSTANCE.getNode("org.stagecraft.pydev.ui").getBoolean(PyDevOffer.OFFERED, false),
                "offered once per workspace");
        assertTrue(PyDev.HOW_TO.contains(PyDev.UPDATE_SITE));
        popup.close();
    }

    @Test
    void installPyDevOpensTheCommandOfP2sInstallNewSoftware() {
        ICommandService commands = PlatformUI.getWorkbench().getService(ICommandService.class);
        Command install = commands.getCommand(PyDev.INSTALL_COMMAND);
        assertTrue(install.isDefined(), PyDev.INSTALL_COMMAND + " is p2's Install New Software command");
        assertTrue(install.isHandled(), "p2's UI handles it");
        Command ours = commands.getCommand("org.stagecraft.pydev.ui.installPyDev");
        assertTrue(ours.isDefined() && ours.isHandled(), "Help > Install PyDev...");
    }

    @Test
    void pythonFilesOpenInTheTextEditorUntilPyDevIsThere() throws Exception {
        IProject p = ResourcesPlugin.getWorkspace().getRoot().getProject("no-pydev-" + System.nanoTime());
        p.create(new NullProgressMonitor());
        p.open(new NullProgressMonitor());
        try {
            IFile robot = p.getFile("robot.py");
            robot.create(new ByteArrayInputStream("print('hi')\n".getBytes(StandardCharsets.UTF_8)), true, new NullProgressMonitor());
            IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
            IEditorPart editor = IDE.openEditor(page, robot);
            assertInstanceOf(TextEditor.class, editor);
            assertEquals("org.stagecraft.pydev.ui.pythonText", editor.getSite().getId());
            page.closeEditor(editor, false);
        } finally {
            p.delete(true, true, new NullProgressMonitor());
        }
    }
}
