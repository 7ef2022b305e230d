package org.stagecraft.player.it;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.stagecraft.tools.process.SupervisedTool;
import org.stagecraft.tools.process.ToolListener;
import org.stagecraft.tools.process.ToolState;

/**
 * Everything a session's tools and the session itself said, as the launch's consoles show it: "TOOL|STREAM|line"
 * ("session" for the session's own lines) and "TOOL|STATE|FROM->TO detail".
 */
final class SessionConsole implements ToolListener {
    final List<String> lines = new CopyOnWriteArrayList<>();

    @Override
    public void output(SupervisedTool tool, Stream stream, String line) {
        lines.add((tool == null ? "session" : tool.name()) + "|" + stream + "|" + line); // null: the session itself
    }

    @Override
    public void stateChanged(SupervisedTool tool, ToolState from, ToolState to, String detail) {
        lines.add(tool.name() + "|STATE|" + from + "->" + to + " " + detail);
    }

    @Override
    public String toString() {
        return String.join("\n", lines);
    }
}
