package org.stagecraft.spy.log;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.session.SessionFramer;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/** Writes the shared traces into spy logs the way the spy would, and remembers what went in. */
final class TraceLogs {
    private TraceLogs() {
    }

    record StreamKey(int conn, Direction dir) {
    }

    /** What a trace put into a log. */
    static final class Expected {
        final Map<StreamKey, ByteArrayOutputStream> streams = new LinkedHashMap<>();
        final List<SessionEvent> wire = new ArrayList<>();
        final Map<Integer, Long> opened = new LinkedHashMap<>();
        final Map<Integer, Long> closed = new LinkedHashMap<>();
        final Map<Integer, Integer> ports = new LinkedHashMap<>();
        long banners;
        long frames;
        long unframed;
        long rawBytes;
        Map<String, String> header = Map.of();

        byte[] stream(int conn, Direction dir) {
            ByteArrayOutputStream s = streams.get(new StreamKey(conn, dir));
            return s == null ? new byte[0] : s.toByteArray();
        }
    }

    static Path tracesDir() {
        return TraceCorpus.dir();
    }

    static List<Path> all() {
        return TraceCorpus.all();
    }

    static long nanos(double t) {
        return Math.round(t * 1e9);
    }

    /** Frames the trace and writes every event into {@code log}; does not close it. */
    static Expected write(Path trace, SpyLogWriter log) throws IOException {
        Expected x = new Expected();
        SessionFramer framer = new SessionFramer(e -> {
            try {
                log.wire(nanos(e.t()), e.stream().conn(), e.stream().port(), e.stream().dir(), e.event());
            } catch (IOException ex) {
                throw new UncheckedIOException(ex);
            }
            x.wire.add(e);
            switch (e.event()) {
                case WireEvent.Banner b -> x.banners++;
                case WireEvent.Frame f -> x.frames++;
                case WireEvent.Unframed u -> x.unframed++;
            }
        });
        double last = 0;
        try (TraceReader reader = new TraceReader(trace)) {
            for (TraceRecord r = reader.next(); r != null; r = reader.next()) {
                switch (r) {
                    case TraceRecord.Header h -> x.header = h.fields();
                    case TraceRecord.Chunk c -> {
                        last = c.t();
                        x.streams.computeIfAbsent(new StreamKey(c.stream().conn(), c.stream().dir()),
                                k -> new ByteArrayOutputStream()).writeBytes(c.data());
                        x.rawBytes += c.data().length;
                        x.ports.putIfAbsent(c.stream().conn(), c.stream().port());
                        framer.chunk(c.t(), c.stream(), c.data());
                    }
                    case TraceRecord.Lifecycle l -> {
                        last = l.t();
                        if (l.isClose()) {
                            framer.close(l.t(), l.conn());
                            log.connectionClosed(nanos(l.t()), l.conn(), "trace close");
                            x.closed.put(l.conn(), nanos(l.t()));
                        } else {
                            log.connectionOpened(nanos(l.t()), l.conn(), "trace client", "0.0.0.0:" + l.port(),
                                    "localhost:" + l.port());
                            x.opened.put(l.conn(), nanos(l.t()));
                        }
                    }
                }
            }
        }
        framer.endAll(last);
        return x;
    }

    /** Writes a whole trace into a new log file. */
    static Expected writeFile(Path trace, Path log, Map<String, String> metadata) throws IOException {
        try (SpyLogWriter w = SpyLogWriter.create(log, metadata)) {
            return write(trace, w);
        }
    }
}
