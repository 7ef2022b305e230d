package org.stagecraft.recording.trace;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.session.SessionFramer;

/** Runs a whole trace through a {@link SessionFramer}: the framed events of a recording, in order. */
public final class TraceFraming {
    private TraceFraming() {
    }

    /**
     * Reads the trace and delivers every banner, message and unframed piece.
     *
     * @return the trace's header
     */
    public static TraceRecord.@Nullable Header frame(Path trace, Consumer<? super SessionEvent> sink) throws IOException {
        try (TraceReader reader = new TraceReader(trace)) {
            return frame(reader, sink);
        }
    }

    public static TraceRecord.@Nullable Header frame(TraceReader reader, Consumer<? super SessionEvent> sink) throws IOException {
        return frame(reader, sink, l -> {
        });
    }

    /**
     * As {@link #frame(TraceReader, Consumer)}, also telling {@code connections} of every open and
     * close record in its place: an open before the connection's first bytes, a close after the
     * bytes its end leaves unframed. Whatever was framed when a bad line stops the reading is
     * delivered (the streams are ended) before the exception is thrown.
     */
    public static TraceRecord.@Nullable Header frame(TraceReader reader, Consumer<? super SessionEvent> sink,
            Consumer<? super TraceRecord.Lifecycle> connections) throws IOException {
        SessionFramer framer = new SessionFramer(sink);
        TraceRecord.Header header = null;
        double last = 0;
        try {
            for (TraceRecord r = reader.next(); r != null; r = reader.next()) {
                switch (r) {
                    case TraceRecord.Header h -> header = h;
                    case TraceRecord.Chunk c -> {
                        last = c.t();
                        framer.chunk(c.t(), c.stream(), c.data());
                    }
                    case TraceRecord.Lifecycle l -> {
                        last = l.t();
                        if (l.isClose()) {
                            framer.close(l.t(), l.conn());
                        }
                        connections.accept(l);
                    }
                }
            }
        } finally {
            framer.endAll(last);
        }
        return header;
    }
}
