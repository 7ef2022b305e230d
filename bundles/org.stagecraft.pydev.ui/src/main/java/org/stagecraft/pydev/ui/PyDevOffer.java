package org.stagecraft.pydev.ui;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.notifications.NotificationPopup;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Link;
import org.eclipse.ui.IStartup;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;
import org.osgi.service.prefs.BackingStoreException;

/**
 * On the first start without PyDev (per workspace), a notification says what PyDev adds and offers
 * to install it (p2's install wizard). Help &gt; Install PyDev... stays until PyDev is there.
 */
public final class PyDevOffer implements IStartup {
    /** Instance preference: the offer was shown in this workspace. */
    public static final String OFFERED = "pydevOffered";
    static final String NODE = "org.stagecraft.pydev.ui";

    /** The popup last shown (for tests). */
    private static volatile @Nullable NotificationPopup shown;

    @Override
    public void earlyStartup() {
        if (PyDev.installed() || Boolean.getBoolean("stagecraft.noPyDevOffer") || Boolean.getBoolean("stagecraft.demo")) {
            return;
        }
        IEclipsePreferences prefs = InstanceScope.INSTANCE.getNode(NODE);
        if (prefs.getBoolean(OFFERED, false)) {
            return;
        }
        PlatformUI.getWorkbench().getDisplay().asyncExec(() -> {
            show(PlatformUI.getWorkbench().getDisplay());
            prefs.putBoolean(OFFERED, true);
            try {
                prefs.flush();
            } catch (BackingStoreException e) {
                ILog.of(PyDevOffer.class).log(Status.warning("cannot save " + OFFERED, e));
            }
        });
    }

    /** Shows the offer (on the UI thread). */
    public static NotificationPopup show(Display display) {
        NotificationPopup[] popup = new NotificationPopup[1];
        popup[0] = NotificationPopup.forDisplay(display).title("Get PyDev for Python robot programs", true).content(parent -> {
            Link link = new Link(parent, SWT.WRAP);
            link.setText(PyDev.HOW_TO.replace("Help > Install PyDev...", "<a>Help > Install PyDev...</a>") + "\n\n<a>Install PyDev...</a>");
            link.addListener(SWT.Selection, e -> {
                popup[0].close();
                IWorkbenchWindow w = PyDev.window();
                if (w != null) {
                    PyDev.openInstall(w);
                }
            });
            return link;
        }).delay(60_000).build();
        popup[0].open();
        shown = popup[0];
        return popup[0];
    }

    public static @Nullable NotificationPopup lastShown() {
        return shown;
    }
}
