package org.stagecraft.tools.process;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/** A listener that keeps everything a tool reports, with waits that end on a condition or fail on a timeout. */
public final class Recorder implements ToolListener {
    public record Line(String tool, Stream stream, String text) {
    }

    public record Change(String tool, ToolState from, ToolState to, String detail) {
    }

    public final List<Line> lines = new CopyOnWriteArrayList<>();
    public final List<Change> changes = new CopyOnWriteArrayList<>();
    private final BlockingQueue<Object> events = new LinkedBlockingQueue<>();

    @Override
    public void output(SupervisedTool tool, Stream stream, String line) {
        Line l = new Line(tool == null ? null : tool.name(), stream, line);
        lines.add(l);
        events.add(l);
    }

    @Override
    public void stateChanged(SupervisedTool tool, ToolState from, ToolState to, String detail) {
        Change c = new Change(tool.name(), from, to, detail);
        changes.add(c);
        events.add(c);
    }

    /** Waits for a line (already seen or coming) that satisfies {@code p}. */
    public Line awaitLine(Predicate<Line> p, Duration timeout) throws InterruptedException {
        return await(Line.class, p, timeout);
    }

    public Change awaitChange(Predicate<Change> p, Duration timeout) throws InterruptedException {
        return await(Change.class, p, timeout);
    }

    private synchronized <T> T await(Class<T> type, Predicate<T> p, Duration timeout) throws InterruptedException {
        for (Object o : type == Line.class ? List.<Object>copyOf(lines) : List.<Object>copyOf(changes)) {
            if (p.test(type.cast(o))) {
                return type.cast(o);
            }
        }
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            Object o = events.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            if (o == null) {
                throw new AssertionError("timed out after " + timeout + " waiting for a " + type.getSimpleName()
                        + "; lines: " + lines + "; changes: " + changes);
            }
            if (type.isInstance(o) && p.test(type.cast(o))) {
                return type.cast(o);
            }
        }
    }

    public List<ToolState> states(String tool) {
        return changes.stream().filter(c -> tool.equals(c.tool())).map(Change::to).toList();
    }
}
