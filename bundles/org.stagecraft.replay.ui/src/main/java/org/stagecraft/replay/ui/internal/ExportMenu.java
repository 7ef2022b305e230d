package org.stagecraft.replay.ui.internal;

import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.stagecraft.replay.ui.SessionLogEditor;

/** The editor's Export menu: CSV (the inspector's filter, a time range), Player writelog, MCAP with JSON. */
public final class ExportMenu {
    private ExportMenu() {
    }

    public static void show(Composite anchor, SessionLogEditor editor) {
        Menu menu = new Menu(anchor.getShell(), SWT.POP_UP);
        item(menu, "CSV (inspector filter, time range)\u2026", editor);
        item(menu, "Player writelog (whole log)\u2026", editor);
        item(menu, "MCAP with JSON channels (Foxglove)\u2026", editor);
        Point at = anchor.toDisplay(anchor.getSize().x - 120, anchor.getSize().y);
        menu.setLocation(at);
        menu.setVisible(true);
    }

    private static void item(Menu menu, String text, SessionLogEditor editor) {
        MenuItem i = new MenuItem(menu, SWT.PUSH);
        i.setText(text);
        i.addListener(SWT.Selection, e -> MessageDialog.openInformation(menu.getShell(), "Export",
                "Export comes with org.stagecraft.replay.export."));
    }
}
