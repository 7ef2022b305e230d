package org.stagecraft.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Iterator;
import java.util.function.Consumer;

import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.session.StreamId;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * The framed events of a recording, whatever its format: a spy log (MCAP, told by its magic bytes) or
 * a player-trace (JSON lines).
 */
final class Recordings {
    private Recordings() {
    }

    static boolean isSpyLog(Path file) throws IOException {
        byte[] head = new byte[8];
        try (InputStream in = Files.newInputStream(file)) {
            int n = in.readNBytes(head, 0, head.length);
            return n == head.length && SpyLogReader.isMcap(head);
        }
    }

    /**
     * Delivers every banner, message and unframed piece in order (a log's: log-time order). A damaged
     * chunk of a spy log is skipped; @return what could not be read, for the command to report.
     */
    static LogRecovery frame(Path file, Consumer<? super SessionEvent> sink) throws IOException {
        if (!isSpyLog(file)) {
            TraceFraming.frame(file, sink);
            return LogRecovery.NONE;
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
            return new LogRecovery(log.recovered(), intact, log.damage(), entries);
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
