package org.stagecraft.replay;

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
 * A recorded trace as a {@link SessionLog} held in memory, built with the trace reader, the framer
 * and the decoder only, so export tests stand on readers other than the ones they test.
 */
public final class TraceLogs {
    private TraceLogs() {
    }

    public static final PlayerDecoder DECODER = new PlayerDecoder(CodecRegistry.standard());

    public static SessionLog open(Path trace) throws IOException {
        Map<Integer, ConnectionInfo> conns = new LinkedHashMap<>();
        List<LogMessage> out = new ArrayList<>();
        TraceFraming.frame(trace, e -> {
            ConnectionInfo c = conns.computeIfAbsent(e.stream().conn(), k -> new ConnectionInfo(k, e.stream().port(),
                    "127.0.0.1:" + (40000 + k), "127.0.0.1:" + e.stream().port(), "127.0.0.1:" + e.stream().port()));
            long t = Math.round(e.t() * 1e9);
            switch (e.event()) {
                case WireEvent.Banner b -> out.add(new LogMessage(t, c, e.stream().dir(), b.offset(),
                        LogMessage.Kind.BANNER, b.bytes(), null, ""));
                case WireEvent.Frame f -> out.add(new LogMessage(t, c, e.stream().dir(), f.offset(),
                        LogMessage.Kind.FRAME, f.bytes(), DECODER.decode(f), ""));
                case WireEvent.Unframed u -> out.add(new LogMessage(t, c, e.stream().dir(), u.offset(),
                        LogMessage.Kind.UNFRAMED, u.bytes(), null, u.reason()));
            }
        });
        return new ListLog(trace, List.copyOf(conns.values()), out);
    }

    /** Every message of a log, from a cursor. */
    public static List<LogMessage> all(SessionLog log) throws IOException {
        List<LogMessage> out = new ArrayList<>();
        try (LogCursor c = log.cursor(Long.MIN_VALUE)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                out.add(m);
            }
        }
        return out;
    }

    private record ListLog(Path path, List<ConnectionInfo> connections, List<LogMessage> messages) implements SessionLog {
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
        public List<LogProblem> problems() {
            return List.of();
        }

        @Override
        public LogCursor cursor(long timeNanos) {
            int i = 0;
            while (i < messages.size() && messages.get(i).timeNanos() < timeNanos) {
                i++;
            }
            int start = i;
            return new LogCursor() {
                int at = start;

                @Override
                public void seek(long t) {
                    at = 0;
                    while (at < messages.size() && messages.get(at).timeNanos() < t) {
                        at++;
                    }
                }

                @Override
                public void seekTo(LogMessage m) {
                    at = messages.indexOf(m);
                }

                @Override
                public LogMessage next() {
                    return at < messages.size() ? messages.get(at++) : null;
                }

                @Override
                public LogMessage previous() {
                    return at > 0 ? messages.get(--at) : null;
                }

                @Override
                public void close() {
                }
            };
        }

        @Override
        public void close() {
        }
    }
}
