package org.stagecraft.replay.ui.tests;

import java.util.function.BooleanSupplier;

import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;

/** Waiting on the UI thread without sleeping: the display loop runs until a condition holds or a deadline passes. */
final class Ui {
    private Ui() {
    }

    static void spinUntil(BooleanSupplier condition, long timeoutMillis, String what) {
        Display d = Display.getCurrent();
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out after " + timeoutMillis + " ms waiting for " + what);
            }
            if (!d.readAndDispatch()) {
                d.timerExec(10, () -> { }); // wake up soon: the condition may change on another thread
                d.sleep();
            }
        }
    }

    /** Runs pending UI events (async updates already queued). */
    static void drain() {
        Display d = Display.getCurrent();
        while (d.readAndDispatch()) {
            // keep going
        }
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
