package org.stagecraft.tools.process;

import org.eclipse.jdt.annotation.Nullable;

/**
 * What a supervised tool reports. Called on the supervisor's own threads; implementations hand
 * work to their UI thread themselves and must not block.
 */
public interface ToolListener {
    enum Stream {
        STDOUT, STDERR, SUPERVISOR
    }

    /**
     * A line of output (without the line break). {@link Stream#SUPERVISOR} lines are the manager's
     * own notes: started, ready, exit codes, restarts.
     */
    void output(@Nullable SupervisedTool tool, Stream stream, String line);

    /** The tool moved from {@code from} to {@code to}; {@code detail} says why (e.g. "exit code 3"). */
    void stateChanged(SupervisedTool tool, ToolState from, ToolState to, String detail);

    ToolListener NONE = new ToolListener() {
        @Override
        public void output(@Nullable SupervisedTool tool, Stream stream, String line) {
        }

        @Override
        public void stateChanged(SupervisedTool tool, ToolState from, ToolState to, String detail) {
        }
    };
}
