package org.stagecraft.replay.log;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

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
    private final List<LogProblem> importProblems;
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
            byId.put(c.conn(), EntryConverter.named(c.conn(), c.port(), c.client(), c.listen(), c.upstream()));
        }
        this.connections = List.copyOf(byId.values());
        this.converter = new EntryConverter(codecs, Collections.unmodifiableMap(byId));
        this.importProblems = List.copyOf(importProblems);
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

    /**
     * The import's problems, then the log's own: no summary (a note, or a loss when its last record
     * was cut off) and each damaged part skipped. Damage inside an indexed log is found when its chunk
     * is read, so the list can grow while the log is read; ask again after reading.
     */
    @Override
    public List<LogProblem> problems() {
        List<LogProblem> p = new ArrayList<>(importProblems);
        if (format == LogFormat.SPY_LOG && reader.recovered()) {
            String cutOff = reader.cutOffEnd();
            p.add(new LogProblem("end of file", reader.endTimeNanos(), "the log has no summary (cut off, or still being"
                    + " written): read by scanning, " + reader.chunkCount() + " complete chunks recovered up to "
                    + seconds(reader.endTimeNanos() - reader.startTimeNanos()) + " s"
                    + (cutOff == null ? "" : "; the incomplete record after them is lost: " + cutOff), cutOff != null));
        }
        for (String part : reader.skippedParts()) {
            p.add(new LogProblem("damaged part", reader.endTimeNanos(), part + "; skipped, its messages are missing"));
        }
        return p;
    }

    @Override
    public List<HoldEntry> holdEntries() throws IOException {
        return reader.holdEntries();
    }

    @Override
    public List<LogMessage> holdRows() throws IOException {
        // a held-back message is the program's own, on its row in the wire channel (marked there): not twice
        return reader.holdEntries().stream().filter(e -> e.action() != HoldEntry.Action.HELD_BACK).map(converter::hold).toList();
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
