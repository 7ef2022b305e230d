package org.stagecraft.demo.ui;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.debug.core.model.IProcess;
import org.eclipse.debug.core.model.IStreamMonitor;
import org.eclipse.debug.core.model.IStreamsProxy;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.ui.launch.SessionParts;

/**
 * What the session's parts print, taken from their consoles as it is printed. The recorded peers'
 * reports: each pass of the recorded robot program and each connection the recorded Player served
 * says whether the other side sent exactly the recorded bytes, which is the end-to-end check that the
 * spy in between relayed every byte unchanged. And Player's console (its first and its latest lines,
 * standard error marked), so that whoever reads the status sees what Player said, errors included.
 */
final class PartReports {
    private static final int MAX = 100;
    /** Player's console: the first lines (startup, where most errors are) and the latest ones. */
    private static final int CONSOLE_HEAD = 60;
    private static final int CONSOLE_TAIL = 60;
    static final String STDERR_MARK = "[stderr] ";

    private final List<String> lines = new ArrayList<>();
    private final List<String> consoleHead = new ArrayList<>();
    private final List<String> consoleTail = new ArrayList<>();
    private long consoleLines;

    /** Follows the reports of {@code partNames} (those that exist) and the console of {@code consolePart}. */
    void listen(SessionParts parts, String consolePart, String... partNames) {
        for (String name : partNames) {
            IStreamsProxy streams = streams(parts, name);
            if (streams != null) {
                follow(streams.getOutputStreamMonitor(), text -> add(name, text));
            }
        }
        IStreamsProxy console = streams(parts, consolePart);
        if (console != null) {
            follow(console.getOutputStreamMonitor(), text -> console(text, ""));
            follow(console.getErrorStreamMonitor(), text -> console(text, STDERR_MARK));
        }
    }

    /**
     * What the part printed before we looked (its banner, for one: the session started it before the
     * demo gets its parts), then everything it prints; a stream monitor that appends under its own
     * lock (as the session's do) cannot slip a piece in between.
     */
    private static void follow(IStreamMonitor monitor, java.util.function.Consumer<String> to) {
        synchronized (monitor) {
            String before = monitor.getContents();
            if (before != null && !before.isEmpty()) {
                to.accept(before);
            }
            monitor.addListener((text, m) -> to.accept(text));
        }
    }

    private static @Nullable IStreamsProxy streams(SessionParts parts, String name) {
        IProcess p = parts.part(name);
        IStreamsProxy streams = p == null ? null : p.getStreamsProxy();
        if (streams == null) {
            DemoLog.warn("no console output of '" + name + "' to follow");
        }
        return streams;
    }

    private synchronized void add(String part, String text) {
        for (String line : text.split("\\R")) {
            if (line.contains(": pass ") || line.contains(": served ")) {
                lines.add(part + ": " + line);
                if (lines.size() > MAX) {
                    lines.remove(0);
                }
            }
        }
    }

    private synchronized void console(String text, String mark) {
        for (String line : text.split("\\R")) {
            if (line.isBlank()) {
                continue;
            }
            consoleLines++;
            if (consoleHead.size() < CONSOLE_HEAD) {
                consoleHead.add(mark + line);
            } else {
                consoleTail.add(mark + line);
                if (consoleTail.size() > CONSOLE_TAIL) {
                    consoleTail.remove(0);
                }
            }
        }
    }

    synchronized List<String> lines() {
        return List.copyOf(lines);
    }

    /** Player's console so far: its first lines, "... N lines ..." where lines were left out, its latest lines. */
    synchronized List<String> console() {
        List<String> out = new ArrayList<>(consoleHead);
        long omitted = consoleLines - consoleHead.size() - consoleTail.size();
        if (omitted > 0) {
            out.add("... " + omitted + " lines ...");
        }
        out.addAll(consoleTail);
        return out;
    }
}
