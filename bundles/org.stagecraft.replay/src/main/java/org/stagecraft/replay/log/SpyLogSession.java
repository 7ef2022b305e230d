package org.stagecraft.replay.log;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A {@link SessionLog} on a spy log file: the file the user opened, or a spy log an import wrote
 * (then {@code cleanup} deletes it on close). Opening reads the summary and index, not the chunks;
 * a log without a summary (cut off, or still being written) is recovered by scanning its records.
 */
final class SpyLogSession implements SessionLog {
    private final Path path;
    private final LogFormat format;
    private final SpyLogReader reader;
    private final List<ConnectionInfo> connections;
    private final EntryConverter converter;
    private final List<LogProblem> problems;
    private final Runnable cleanup;

    SpyLogSession(Path path, LogFormat format, SpyLogReader reader, CodecRegistry codecs, List<LogProblem> importProblems,
            Runnable cleanup) throws IOException {
        this.path = path;
        this.format = format;
        this.reader = reader;
        this.cleanup = cleanup;
        Map<Integer, ConnectionInfo> byId = new LinkedHashMap<>();
        // from the summary when the log records addresses with its channels; else from the open events
        List<LogConnection> known = reader.indexedConnections();
        for (LogConnection c : known.isEmpty() ? reader.connections() : known) {
            byId.put(c.conn(), new ConnectionInfo(c.conn(), c.port(), orElse(c.client(), "connection " + c.conn()),
                    orElse(c.listen(), "port " + c.port()), orElse(c.upstream(), "")));
        }
        this.connections = List.copyOf(byId.values());
        this.converter = new EntryConverter(codecs, Collections.unmodifiableMap(byId));
        List<LogProblem> p = new ArrayList<>(importProblems);
        if (format == LogFormat.SPY_LOG && reader.recovered()) {
            p.add(new LogProblem("end of file", reader.endTimeNanos(), "the log has no summary (cut off, or still being"
                    + " written): read by scanning, " + reader.chunkCount() + " complete chunks recovered up to "
                    + seconds(reader.endTimeNanos() - reader.startTimeNanos()) + " s"));
        }
        if (reader.skippedChunks() > 0) {
            p.add(new LogProblem("file", reader.endTimeNanos(),
                    reader.skippedChunks() + " damaged chunks skipped; their messages are missing"));
        }
        this.problems = List.copyOf(p);
    }

    private static String orElse(@Nullable String s, String other) {
        return s == null || s.isEmpty() ? other : s;
    }

    private static String seconds(long nanos) {
        return String.format(java.util.Locale.ROOT, "%.3f", nanos / 1e9);
    }

    @Override
    public Path path() {
        return path;
    }

    @Override
    public LogFormat format() {
        return format;
    }

    @Override
    public long startNanos() {
        return reader.startTimeNanos();
    }

    @Override
    public long endNanos() {
        return reader.endTimeNanos();
    }

    @Override
    public boolean complete() {
        return !reader.recovered();
    }

    @Override
    public long messageCount() {
        return reader.messageCount();
    }

    @Override
    public List<ConnectionInfo> connections() {
        return connections;
    }

    @Override
    public List<LogProblem> problems() {
        return problems;
    }

    @Override
    public List<HoldEntry> holdEntries() throws IOException {
        return reader.holdEntries();
    }

    @Override
    public LogCursor cursor(long timeNanos) {
        return cursor(timeNanos, SpyLogCursor.BACK_WINDOW);
    }

    /** A cursor that holds at most {@code backWindow} entries for walking back (tests use small ones). */
    LogCursor cursor(long timeNanos, int backWindow) {
        return new SpyLogCursor(reader, converter, reader.startTimeNanos(), timeNanos, backWindow);
    }

    /** The reader underneath, for tools that work on the spy log itself (counts, stream bytes, export). */
    SpyLogReader reader() {
        return reader;
    }

    @Override
    public void close() throws IOException {
        try {
            reader.close();
        } finally {
            cleanup.run();
        }
    }
}
