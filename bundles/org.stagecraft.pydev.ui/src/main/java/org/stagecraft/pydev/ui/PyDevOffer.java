package org.stagecraft.pydev.ui;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.layout.GridLayoutFactory;
import org.eclipse.jface.notifications.NotificationPopup;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Link;
import org.eclipse.ui.IStartup;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PlatformUI;
import org.osgi.service.prefs.BackingStoreException;

/**
 * On the first start without PyDev (per workspace), a notification says what PyDev adds and offers
 * to install it (p2's install wizard); it stays until it is closed. Help &gt; Install PyDev... stays
 * until PyDev is there.
 */
public final class PyDevOffer implements IStartup {
    /** Instance preference: the offer was shown in this workspace. */
    public static final String OFFERED = "pydevOffered";
    static final String NODE = "org.stagecraft.pydev.ui";

    /** The width the offer's text wraps at: within the notification's 400 pixels with its margins. */
    static final int TEXT_WIDTH = 340;
    /** The offer stays until the user closes it or follows a link (a notification's delay of 0: never closes by itself). */
    public static final long STAYS = 0;

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
            // the popup sizes itself from its content's unwrapped size, then narrows to its maximum width:
            // a wrapping text must say the width it wraps at, or its last lines are cut off
            Composite box = new Composite(parent, SWT.NONE);
            box.setLayout(GridLayoutFactory.fillDefaults().create());
            Link link = new Link(box, SWT.WRAP);
            link.setText(PyDev.HOW_TO.replace("Help > Install PyDev...", "<a>Help > Install PyDev...</a>") + "\n\n<a>Install PyDev...</a>");
            link.setLayoutData(GridDataFactory.fillDefaults().grab(true, false).hint(TEXT_WIDTH, SWT.DEFAULT).create());
            link.addListener(SWT.Selection, e -> {
                popup[0].close();
                IWorkbenchWindow w = PyDev.window();
                if (w != null) {
                    PyDev.openInstall(w);
                }
            });
            return box;
        }).delay(STAYS).build();
        popup[0].open();
        shown = popup[0];
        return popup[0];
    }

    public static @Nullable NotificationPopup lastShown() {
        return shown;
    }
}
