package org.stagecraft.demo.ui;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.debug.core.model.IProcess;
import org.eclipse.debug.core.model.IStreamsProxy;
import org.stagecraft.tools.ui.launch.SessionParts;

/**
 * The recorded peers' reports, taken from their consoles as they are printed: each pass of the
 * recorded robot program and each connection the recorded Player served says whether the other side
 * sent exactly the recorded bytes, which is the end-to-end check that the spy in between relayed
 * every byte unchanged.
 */
final class PartReports {
    private static final int MAX = 100;
    private final List<String> lines = new ArrayList<>();

    void listen(SessionParts parts, String... partNames) {
        for (String name : partNames) {
            IProcess p = parts.part(name);
            IStreamsProxy streams = p == null ? null : p.getStreamsProxy();
            if (streams == null) {
                DemoLog.warn("no console output of '" + name + "' to follow");
                continue;
            }
            streams.getOutputStreamMonitor().addListener((text, monitor) -> add(name, text));
        }
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

    synchronized List<String> lines() {
        return List.copyOf(lines);
    }
}
