package org.stagecraft.tests.support;

import java.util.function.BooleanSupplier;

import org.eclipse.swt.widgets.Display;

/**
 * Waiting on the UI thread without sleeping: the display loop runs (so what the test waits for can be
 * drawn) until a condition holds or a deadline passes.
 */
public final class UiWait {
    private UiWait() {
    }

    public static void spinUntil(BooleanSupplier condition, long timeoutMillis, String what) {
        Display d = Display.getCurrent();
        if (d == null) {
            throw new IllegalStateException("UiWait.spinUntil runs on the UI thread; off it, use Await");
        }
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out after " + timeoutMillis + " ms waiting for " + what);
            }
            if (!d.readAndDispatch()) {
                d.timerExec(10, () -> { }); // wake the loop again soon: the condition may change off the UI thread
                d.sleep();
            }
        }
    }

    /** Runs the UI events already queued (async updates). */
    public static void drain() {
        Display d = Display.getCurrent();
        while (d.readAndDispatch()) {
            // keep going
        }
    }
}
