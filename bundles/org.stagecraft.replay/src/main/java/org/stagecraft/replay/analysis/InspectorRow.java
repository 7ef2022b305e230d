package org.stagecraft.replay.analysis;

import org.stagecraft.replay.log.LogMessage;

/**
 * One row of the packet inspector.
 *
 * @param message  the log entry
 * @param gapBytes bytes of its stream the recorder missed just before it (0: none seen)
 */
public record InspectorRow(LogMessage message, long gapBytes) {

    /** Whether the row is to be marked: a decode problem, bytes that were not a message, or a gap before it. */
    public boolean marked() {
        return gapBytes > 0 || message.isProblem();
    }
}
