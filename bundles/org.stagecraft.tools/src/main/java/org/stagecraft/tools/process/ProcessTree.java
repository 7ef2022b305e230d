package org.stagecraft.tools.process;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Stops a process together with everything it started. Player forks nothing, but user tools are
 * often shell scripts whose children (a simulator, a logger) would otherwise outlive the session
 * and keep its ports.
 */
public final class ProcessTree {
    private ProcessTree() {
    }

    /**
     * Asks the process and all its descendants to end (SIGTERM), waits up to {@code grace} for them,
     * then kills what is left (SIGKILL) and waits for that too.
     *
     * @return the processes that were part of the tree when the stop began
     */
    public static List<ProcessHandle> stop(ProcessHandle root, Duration grace) {
        // The descendants first: once the root is gone its children are re-parented and no longer found.
        List<ProcessHandle> tree = new ArrayList<>(root.descendants().toList());
        tree.add(0, root);
        for (ProcessHandle p : tree) {
            p.destroy();
        }
        long deadline = System.nanoTime() + grace.toNanos();
        for (ProcessHandle p : tree) {
            if (!awaitExit(p, deadline)) {
                p.destroyForcibly();
            }
        }
        long hardDeadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        for (ProcessHandle p : tree) {
            awaitExit(p, hardDeadline);
        }
        return tree;
    }

    private static boolean awaitExit(ProcessHandle p, long deadlineNanos) {
        long left = deadlineNanos - System.nanoTime();
        if (!p.isAlive()) {
            return true;
        }
        if (left <= 0) {
            return false;
        }
        try {
            p.onExit().get(left, TimeUnit.NANOSECONDS);
            return true;
        } catch (TimeoutException | ExecutionException e) {
            return !p.isAlive();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return !p.isAlive();
        }
    }
}
