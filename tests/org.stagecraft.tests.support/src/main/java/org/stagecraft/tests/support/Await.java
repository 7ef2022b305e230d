package org.stagecraft.tests.support;

import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import org.eclipse.swt.widgets.Display;

/**
 * Waiting off the UI thread (a test that waits for processes, sockets, the workbench): checks a
 * condition other threads make true again and again until it holds or the timeout fails the test.
 * For the platform's states that offer no event to wait on (console documents, the workspace after a
 * refresh, what a view shows). On the UI thread use {@link UiWait} instead: this would block the
 * display the condition waits for.
 */
public final class Await {
    private static final long POLL_NANOS = TimeUnit.MILLISECONDS.toNanos(20);

    private Await() {
    }

    public static void until(String what, Duration timeout, BooleanSupplier condition) {
        until(what, timeout, condition, () -> "");
    }

    /** As {@link #until(String, Duration, BooleanSupplier)}; a timeout also says what {@code state} tells. */
    public static void until(String what, Duration timeout, BooleanSupplier condition, Supplier<String> state) {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out after " + timeout + " waiting until " + what + " " + state.get());
            }
            LockSupport.parkNanos(POLL_NANOS);
        }
    }

    /** Runs {@code work} on the UI thread and returns what it returns; its exception fails the caller. */
    public static <T> T ui(Callable<T> work) {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                result.set(work.call());
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw new AssertionError("on the UI thread: " + failure.get(), failure.get());
        }
        return result.get();
    }

    /** Waits until {@code condition}, checked on the UI thread, holds. */
    public static void untilUi(String what, Duration timeout, Callable<Boolean> condition) {
        until(what, timeout, () -> ui(condition));
    }

    /** As {@link #untilUi(String, Duration, Callable)}; a timeout also says what {@code state} (on the UI thread) tells. */
    public static void untilUi(String what, Duration timeout, Callable<Boolean> condition, Callable<String> state) {
        until(what, timeout, () -> ui(condition), () -> ui(state));
    }
}
