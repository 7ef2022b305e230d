package org.stagecraft.pydev.ui;

import org.eclipse.core.commands.Command;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.commands.ICommandService;
import org.eclipse.ui.handlers.IHandlerService;

/**
 * Whether PyDev is installed, and how to get it: p2's Install New Software wizard, where the
 * product lists PyDev's update site (releng/org.stagecraft.product/stagecraft.p2.inf).
 */
public final class PyDev {
    /** A bundle every PyDev installation has. */
    public static final String BUNDLE = "org.python.pydev";
    public static final String UPDATE_SITE = "https://www.pydev.org/updates";
    /** p2's Help &gt; Install New Software... (org.eclipse.equinox.p2.ui.sdk). */
    public static final String INSTALL_COMMAND = "org.eclipse.equinox.p2.ui.sdk.install";
    public static final String HOW_TO = "PyDev is not installed: Python files open in the plain text editor, and robot programs run "
            + "with the plain interpreter (no Python debugger). Install PyDev for the Python editor, Run/Debug As > Robot Session "
            + "under PyDev and breakpoints: Help > Install PyDev... (or Help > Install New Software..., work with \"PyDev\", "
            + UPDATE_SITE + ").";

    private PyDev() {
    }

    public static boolean installed() {
        return Platform.getBundle(BUNDLE) != null;
    }

    /** Opens p2's install wizard (PyDev's site is one of the available sites); without p2's UI, says what to do. */
    public static void openInstall(IWorkbenchWindow window) {
        @Nullable ICommandService commands = window.getService(ICommandService.class);
        Command install = commands != null ? commands.getCommand(INSTALL_COMMAND) : null;
        if (install != null && install.isDefined()) {
            try {
                window.getService(IHandlerService.class).executeCommand(INSTALL_COMMAND, null);
                return;
            } catch (Exception e) {
                ILog.of(PyDev.class).log(Status.warning("cannot open Install New Software", e));
            }
        }
        MessageDialog.openInformation(window.getShell(), "Install PyDev", "This Stagecraft has no software installer. "
                + "Install PyDev into it with the p2 director from its update site " + UPDATE_SITE + " (feature org.python.pydev.feature).");
    }

    static @Nullable IWorkbenchWindow window() {
        IWorkbenchWindow w = PlatformUI.getWorkbench().getActiveWorkbenchWindow();
        if (w == null && PlatformUI.getWorkbench().getWorkbenchWindowCount() > 0) {
            w = PlatformUI.getWorkbench().getWorkbenchWindows()[0];
        }
        return w;
    }
}
