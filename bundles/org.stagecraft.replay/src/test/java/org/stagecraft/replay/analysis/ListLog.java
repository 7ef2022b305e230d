package org.stagecraft.replay.analysis;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A session log held in a list, for testing the analysis models apart from the file readers: built
 * from a shared trace (framed and decoded here) or from entries a test makes up.
 */
final class ListLog implements SessionLog {
    static final CodecRegistry REGISTRY = CodecRegistry.standard();
    private final List<LogMessage> messages;
    private final List<ConnectionInfo> connections;
    int cursorsOpen;

    ListLog(List<LogMessage> messages) {
        this.messages = List.copyOf(messages);
        Map<Integer, ConnectionInfo> c = new LinkedHashMap<>();
        for (LogMessage m : messages) {
            if (m.connection() != null) {
                c.putIfAbsent(m.connection().id(), m.connection());
            }
        }
        this.connections = List.copyOf(c.values());
    }

    static ConnectionInfo connection(int id, int port) {
        return new ConnectionInfo(id, port, "127.0.0.1:" + (40000 + id), "127.0.0.1:" + port, "127.0.0.1:" + (port + 1000));
    }

    /** The trace's banners and frames (decoded) in trace order. */
    static ListLog ofTrace(Path trace) throws IOException {
        PlayerDecoder decoder = new PlayerDecoder(REGISTRY);
        List<LogMessage> out = new ArrayList<>();
        TraceFraming.frame(trace, e -> {
            ConnectionInfo c = connection(e.stream().conn(), e.stream().port());
            long t = Math.round(e.t() * 1e9);
            switch (e.event()) {
                case WireEvent.Banner b -> out.add(new LogMessage(t, c, e.stream().dir(), b.offset(),
                        LogMessage.Kind.BANNER, b.bytes(), null, ""));
                case WireEvent.Frame f -> out.add(new LogMessage(t, c, e.stream().dir(), f.offset(),
                        LogMessage.Kind.FRAME, f.bytes(), decoder.decode(f), ""));
                case WireEvent.Unframed u -> out.add(new LogMessage(t, c, e.stream().dir(), u.offset(),
                        LogMessage.Kind.UNFRAMED, u.bytes(), null, u.reason()));
            }
        });
        return new ListLog(out);
    }

    List<LogMessage> messages() {
        return messages;
    }

    @Override
    public Path path() {
        return Path.of("list.log");
    }

    @Override
    public LogFormat format() {
        return LogFormat.PLAYER_TRACE;
    }

    @Override
    public long startNanos() {
        return messages.isEmpty() ? 0 : messages.get(0).timeNanos();
    }

    @Override
    public long endNanos() {
        return messages.isEmpty() ? 0 : messages.get(messages.size() - 1).timeNanos();
    }

    @Override
    public boolean complete() {
        return true;
    }

    @Override
    public long messageCount() {
        return messages.stream().filter(m -> m.dir() != null && m.kind() != LogMessage.Kind.DIAGNOSTIC).count();
    }

    @Override
    public List<ConnectionInfo> connections() {
        return connections;
    }

    @Override
    public List<LogProblem> problems() {
        return List.of();
    }

    @Override
    public LogCursor cursor(long timeNanos) {
        Cursor c = new Cursor();
        c.seek(timeNanos);
        cursorsOpen++;
        return c;
    }

    @Override
    public void close() {
    }

    private final class Cursor implements LogCursor {
        int next;

        @Override
        public void seek(long t) {
            int lo = 0, hi = messages.size();
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (messages.get(mid).timeNanos() < t) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            next = lo;
        }

        @Override
        public void seekTo(LogMessage m) {
            seek(m.timeNanos());
            while (next < messages.size() && !messages.get(next).samePlace(m)) {
                next++;
            }
            if (next == messages.size()) {
                throw new IllegalArgumentException("not in this log: " + m);
            }
        }

        @Override
        public LogMessage next() {
            return next < messages.size() ? messages.get(next++) : null;
        }

        @Override
        public LogMessage previous() {
            return next > 0 ? messages.get(--next) : null;
        }

        @Override
        public void close() {
            cursorsOpen--;
        }
    }
}
