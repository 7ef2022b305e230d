package org.stagecraft.replay.ui.internal;

import java.util.concurrent.atomic.AtomicBoolean;

import org.eclipse.swt.widgets.Display;

/**
 * Runs a UI update at most once per period however often it is asked for, from any thread: the replay
 * thread asks after every message and never waits for the display. An update asked for while one is
 * pending is merged into it.
 */
public final class UiThrottle {
    private final Display display;
    private final int periodMillis;
    private final Runnable update;
    private final AtomicBoolean pending = new AtomicBoolean();
    private volatile long lastRun;

    public UiThrottle(Display display, int periodMillis, Runnable update) {
        this.display = display;
        this.periodMillis = periodMillis;
        this.update = update;
    }

    /** Asks for an update (any thread). */
    public void request() {
        if (!pending.compareAndSet(false, true) || display.isDisposed()) {
            return;
        }
        long wait = lastRun + periodMillis - System.currentTimeMillis();
        try {
            if (wait <= 0) {
                display.asyncExec(this::run);
            } else {
                display.asyncExec(() -> display.timerExec((int) wait, this::run));
            }
        } catch (org.eclipse.swt.SWTException disposed) {
            pending.set(false); // the display went away: nothing left to update
        }
    }

    private void run() {
        pending.set(false);
        lastRun = System.currentTimeMillis();
        update.run();
    }
}
