package org.stagecraft.replay.analysis;

import java.util.HashMap;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.log.LogMessage;

/**
 * Finds bytes a recorder missed: each direction of a connection is one byte stream, so an entry
 * that starts later than the previous one ended leaves a gap (e.g. the spy's observation queue
 * overflowed). Fed entries in log order; formats that give no offsets never show a gap.
 */
public final class GapTracker {
    private record Stream(int conn, @Nullable Direction dir) {
    }

    private final Map<Stream, Long> next = new HashMap<>();

    /** Bytes missing just before {@code m} in its stream (0 when none or unknown). */
    public long accept(LogMessage m) {
        if (m.dir() == null || m.streamOffset() < 0 || m.connection() == null
                || m.kind() == LogMessage.Kind.DIAGNOSTIC) {
            return 0;
        }
        Stream s = new Stream(m.connection().id(), m.dir());
        @Nullable Long expected = next.put(s, m.streamOffset() + m.bytes().length);
        return expected != null && m.streamOffset() > expected ? m.streamOffset() - expected : 0;
    }
}
