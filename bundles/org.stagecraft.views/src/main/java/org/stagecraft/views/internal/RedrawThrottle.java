package org.stagecraft.views.internal;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.eclipse.swt.SWTException;
import org.eclipse.swt.widgets.Display;

/**
 * Turns "new data arrived" (from any thread, any number of times) into at most one pending redraw on
 * the UI thread, and at most one frame per {@code minInterval}. Requests arriving while one is pending
 * merge into it, so a burst of data costs one frame of the newest data, never a queue of stale ones.
 */
public final class RedrawThrottle {
    private final Display display;
    private final Runnable draw;
    private final long minIntervalNanos;
    private final AtomicBoolean pending = new AtomicBoolean();
    private long lastFrame = System.nanoTime() - TimeUnit.SECONDS.toNanos(1);

    public RedrawThrottle(Display display, long minIntervalMillis, Runnable draw) {
        this.display = display;
        this.draw = draw;
        this.minIntervalNanos = TimeUnit.MILLISECONDS.toNanos(minIntervalMillis);
    }

    /** Any thread. */
    public void request() {
        if (pending.compareAndSet(false, true)) {
            try {
                display.asyncExec(this::schedule);
            } catch (SWTException e) {
                // the display is gone: nothing left to draw on
            }
        }
    }

    private void schedule() {
        long waitMillis = TimeUnit.NANOSECONDS.toMillis(lastFrame + minIntervalNanos - System.nanoTime());
        if (waitMillis > 0) {
            display.timerExec((int) waitMillis, this::drawNow);
        } else {
            drawNow();
        }
    }

    private void drawNow() {
        pending.set(false); // data arriving during the frame schedules the next one
        lastFrame = System.nanoTime();
        draw.run();
    }
}
