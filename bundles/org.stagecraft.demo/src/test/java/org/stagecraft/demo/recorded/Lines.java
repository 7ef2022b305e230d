package org.stagecraft.demo.recorded;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeoutException;
import java.util.function.Predicate;

import org.stagecraft.tools.process.SupervisedTool;
import org.stagecraft.tools.process.ToolListener;
import org.stagecraft.tools.process.ToolState;

/** Collects the output lines of a session's tools; tests wait for a line with a deadline. */
final class Lines implements ToolListener {
    private final List<String> lines = new ArrayList<>();

    @Override
    public synchronized void output(SupervisedTool tool, Stream stream, String line) {
        lines.add((tool == null ? "session" : tool.spec().name()) + ": " + line);
        notifyAll();
    }

    @Override
    public void stateChanged(SupervisedTool tool, ToolState from, ToolState to, String detail) {
    }

    synchronized String await(Predicate<String> p, Duration within) throws InterruptedException, TimeoutException {
        long deadline = System.nanoTime() + within.toNanos();
        while (true) {
            for (String l : lines) {
                if (p.test(l)) {
                    return l;
                }
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                throw new TimeoutException("no such line within " + within + "; lines: " + lines);
            }
            wait(Math.max(1, left / 1_000_000));
        }
    }
}
