package org.stagecraft.replay.ui.tests;

import java.util.function.BooleanSupplier;

import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.stagecraft.tests.support.UiWait;

/** Waiting on the UI thread without sleeping ({@link UiWait}, shared by the plug-in tests), and pressing buttons. */
final class Ui {
    private Ui() {
    }

    static void spinUntil(BooleanSupplier condition, long timeoutMillis, String what) {
        UiWait.spinUntil(condition, timeoutMillis, what);
    }

    /** Runs pending UI events (async updates already queued). */
    static void drain() {
        UiWait.drain();
    }

    /** The push button with this text under {@code root}, pressed as a click would. */
    static void press(Composite root, String text) {
        Button b = find(root, text);
        if (b == null) {
            throw new AssertionError("no button '" + text + "'");
        }
        b.notifyListeners(org.eclipse.swt.SWT.Selection, new org.eclipse.swt.widgets.Event());
    }

    private static Button find(Composite root, String text) {
        for (Control c : root.getChildren()) {
            if (c instanceof Button b && text.equals(b.getText())) {
                return b;
            }
            if (c instanceof Composite sub) {
                Button found = find(sub, text);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }
}
