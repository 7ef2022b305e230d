package org.stagecraft.recording.trace;

import java.util.Map;

import org.stagecraft.player.session.StreamId;

/** One line of a player-trace file (format "player-trace", version 1). */
public sealed interface TraceRecord {

    /** 1-based line number in the file, for error messages. */
    long line();

    /** Line 1: what was recorded (scenario, Player and Stage commits, world, creation time). */
    record Header(long line, Map<String, String> fields) implements TraceRecord {
        public Header {
            fields = Map.copyOf(fields);
        }
    }

    /** Exactly the bytes one recv() returned on a stream, at time t (seconds since the recorder started). */
    record Chunk(long line, double t, StreamId stream, byte[] data) implements TraceRecord {
    }

    /** A connection was accepted ("open") or finished ("close"). */
    record Lifecycle(long line, double t, int conn, int port, String event) implements TraceRecord {
        public boolean isClose() {
            return "close".equals(event);
        }
    }
}
