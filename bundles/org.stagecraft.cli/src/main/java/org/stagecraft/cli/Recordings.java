package org.stagecraft.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Iterator;
import java.util.Locale;
import java.util.function.Consumer;

import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.session.StreamId;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceFormatException;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.writelog.WritelogImport;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * The framed events of a recording, whatever its format: a spy log (MCAP, told by its magic bytes) or
 * a player-trace (JSON lines).
 */
final class Recordings {
    private Recordings() {
    }

    /**
     * Delivers every banner, message and unframed piece in order (a log's: log-time order). A damaged
     * chunk of a spy log is skipped, and a trace is read up to a line that is not valid; @return what
     * could not be read, for the command to report.
     *
     * @throws IOException naming the file when it cannot be read at all: not the format its name or
     *                     content promises (a {@code .mcap} that is not MCAP, a Player writelog file)
     */
    static LogRecovery frame(Path file, Consumer<? super SessionEvent> sink) throws IOException {
        byte[] head = SessionLogs.head(file);
        if (!SpyLogReader.isMcap(head)) {
            if (String.valueOf(file.getFileName()).toLowerCase(Locale.ROOT).endsWith(".mcap")) {
                throw new IOException(SessionLogs.notMcap(file, head));
            }
            if (WritelogImport.looksLikeWritelog(head)) {
                throw new IOException(file + ": a Player writelog file; decode and stats read spy logs and"
                        + " player-traces (export reads writelog files too, e.g. export FILE --format csv)");
            }
            return trace(file, sink);
        }
        long entries = 0;
        try (SpyLogReader log = SpyLogReader.open(file)) {
            Iterator<LogEntry> it = log.entries();
            while (true) {
                LogEntry e;
                try {
                    if (!it.hasNext()) {
                        break;
                    }
                    e = it.next();
                } catch (UncheckedIOException ex) {
                    throw ex.getCause();
                }
                entries++;
                if (e instanceof LogEntry.Wire w) {
                    sink.accept(new SessionEvent(w.timeNanos() / 1e9, new StreamId(w.conn(), w.port(), w.dir()),
                            event(w)));
                }
            }
            int intact = log.recovered() ? log.chunkCount() : log.chunkCount() - log.skippedChunks();
            return new LogRecovery(log.recovered(), intact, log.damage(), log.messagesLost(), entries, null);
        }
    }

    /** A player-trace, up to its end or to the first line that is not valid. */
    private static LogRecovery trace(Path file, Consumer<? super SessionEvent> sink) throws IOException {
        long[] events = { 0 };
        try {
            TraceFraming.frame(file, e -> {
                events[0]++;
                sink.accept(e);
            });
            return LogRecovery.whole(events[0]);
        } catch (TraceFormatException e) {
            return LogRecovery.stoppedAt(e, events[0]);
        }
    }

    /** The framer event a wire entry recorded. */
    static WireEvent event(LogEntry.Wire w) {
        byte[] b = w.bytes();
        return switch (w.kind()) {
            case BANNER -> new WireEvent.Banner(w.streamOffset(), b);
            case UNFRAMED -> new WireEvent.Unframed(w.streamOffset(), b, w.reason());
            case FRAME -> {
                if (b.length < MessageHeader.SIZE) {
                    yield new WireEvent.Unframed(w.streamOffset(), b, "log entry shorter than a header");
                }
                MessageHeader h = MessageHeader.read(b, 0);
                if (h.sizeUnsigned() != b.length - MessageHeader.SIZE) {
                    yield new WireEvent.Unframed(w.streamOffset(), b, "log entry does not match its header size");
                }
                yield new WireEvent.Frame(w.streamOffset(), h, Arrays.copyOfRange(b, MessageHeader.SIZE, b.length));
            }
        };
    }
}
