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
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Link;
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
        // issue 24, item 7: the whole text shows (the link to Help > Install PyDev... was cut off), and the
        // offer stays until it is closed (it vanished by itself)
        Link link = find(popup.getShell(), Link.class);
        assertNotNull(link, "the offer's text");
        Point needed = link.computeSize(link.getSize().x, SWT.DEFAULT);
        assertTrue(link.getSize().y >= needed.y, "the text is " + needed.y + " pixels high at its width, shown in "
                + link.getSize().y);
        Rectangle inShell = popup.getShell().getDisplay().map(link.getParent(), popup.getShell(), link.getBounds());
        assertTrue(popup.getShell().getClientArea().contains(inShell.x, inShell.y + inShell.height - 1),
                "the text's last line is inside the popup: " + inShell + " in " + popup.getShell().getClientArea());
        assertEquals(PyDevOffer.STAYS, popup.getDelayClose(), "no closing by itself");
        popup.close();
    }

    /** The first control of {@code type} in the tree under {@code c}, or null. */
    private static <T extends Control> T find(Control c, Class<T> type) {
        if (type.isInstance(c)) {
            return type.cast(c);
        }
        if (c instanceof Composite parent) {
            for (Control child : parent.getChildren()) {
                T found = find(child, type);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
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
