package org.stagecraft.player.session;

import java.util.HashMap;
import java.util.Map;
import java.util.function.Consumer;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;

/**
 * Frames every direction of every connection of a session (a trace, a log, the spy), with one
 * {@link PlayerFramer} per connection and direction. Events come out in the order the chunks
 * that complete them come in.
 */
public final class SessionFramer {
    private final Consumer<? super SessionEvent> sink;
    private final Map<StreamId, PlayerFramer> framers = new HashMap<>();
    private double now;

    public SessionFramer(Consumer<? super SessionEvent> sink) {
        this.sink = sink;
    }

    /** Feeds bytes one recv() returned on a stream at time t. */
    public void chunk(double t, StreamId stream, byte[] data, int off, int len) {
        now = t;
        framer(stream).accept(data, off, len);
    }

    public void chunk(double t, StreamId stream, byte[] data) {
        chunk(t, stream, data, 0, data.length);
    }

    /** The connection closed: both directions end, and unfinished bytes are reported. */
    public void close(double t, int conn) {
        now = t;
        framers.entrySet().removeIf(e -> {
            if (e.getKey().conn() == conn) {
                e.getValue().end();
                return true;
            }
            return false;
        });
    }

    /** Ends every stream still open (end of a recording). */
    public void endAll(double t) {
        now = t;
        for (PlayerFramer f : framers.values()) {
            f.end();
        }
        framers.clear();
    }

    private PlayerFramer framer(StreamId stream) {
        PlayerFramer f = framers.get(stream);
        if (f == null) {
            f = new PlayerFramer(stream.dir(), e -> sink.accept(new SessionEvent(now, stream, e)));
            framers.put(stream, f);
        }
        return f;
    }

    /** Convenience for callers that know the direction by label. */
    public static StreamId stream(int conn, int port, String dirLabel) {
        return new StreamId(conn, port, Direction.fromLabel(dirLabel));
    }
}
