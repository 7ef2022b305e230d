package org.stagecraft.replay.log;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * A two-way cursor over a spy log. The log's order is by time, ties in file order; a position is
 * "before the {@code rank}-th entry with time {@code time}", which stays valid however the cursor got
 * there. Forward it streams through the reader's time-ordered iterator; backward it reads a bounded
 * window of the entries just before the position (through the chunk index, so the cost does not grow
 * with the log), and walks back through it.
 */
final class SpyLogCursor implements LogCursor {
    /** At most this many entries are held for walking back. */
    static final int BACK_WINDOW = 2048;
    private static final long FIRST_BACK_SPAN = 250_000_000L;

    private record Ranked(LogEntry entry, long time, int rank) {
    }

    private final SpyLogReader reader;
    private final EntryConverter converter;
    private final long startNanos;
    private final int backWindow;

    private long posTime;
    private int posRank;
    /** Streams forward from the position; null until needed, dropped when the position moves back. */
    private @Nullable Iterator<LogEntry> forward;
    /** Entries just before the position, in log order; the last one is the previous entry. */
    private final List<Ranked> back = new ArrayList<>();
    private long backSpan = FIRST_BACK_SPAN;
    private boolean closed;

    SpyLogCursor(SpyLogReader reader, EntryConverter converter, long startNanos, long timeNanos, int backWindow) {
        this.backWindow = backWindow;
        this.reader = reader;
        this.converter = converter;
        this.startNanos = startNanos;
        seek(timeNanos);
    }

    @Override
    public void seek(long timeNanos) {
        moveTo(timeNanos, 0);
    }

    private void moveTo(long time, int rank) {
        posTime = time;
        posRank = rank;
        forward = null;
        back.clear();
    }

    @Override
    public void seekTo(LogMessage message) throws IOException {
        checkOpen();
        Iterator<LogEntry> it = entriesFrom(message.timeNanos());
        int rank = 0;
        while (it.hasNext()) {
            LogEntry e = it.next();
            if (e.timeNanos() != message.timeNanos()) {
                break;
            }
            if (message.samePlace(converter.convert(e))) {
                moveTo(message.timeNanos(), rank);
                return;
            }
            rank++;
        }
        throw new IllegalArgumentException("the message at " + message.timeNanos() + " ns is not in this log");
    }

    @Override
    public @Nullable LogMessage next() throws IOException {
        checkOpen();
        Iterator<LogEntry> forward = this.forward;
        if (forward == null) {
            forward = entriesFrom(posTime);
            this.forward = forward;
            for (int skipped = 0; skipped < posRank && forward.hasNext(); skipped++) {
                forward.next(); // entries at the position's time that lie before it
            }
        }
        if (!hasNext(forward)) {
            return null;
        }
        LogEntry e = forward.next();
        int rank = e.timeNanos() == posTime ? posRank : 0;
        posTime = e.timeNanos();
        posRank = rank + 1;
        if (!back.isEmpty()) {
            back.add(new Ranked(e, e.timeNanos(), rank));
            if (back.size() > backWindow) {
                back.remove(0);
            }
        }
        return converter.convert(e);
    }

    @Override
    public @Nullable LogMessage previous() throws IOException {
        checkOpen();
        if (back.isEmpty() && !fillBack()) {
            return null;
        }
        Ranked r = back.remove(back.size() - 1);
        posTime = r.time();
        posRank = r.rank();
        forward = null;
        return converter.convert(r.entry());
    }

    /** Reads the entries just before the position into {@link #back}; false at the start of the log. */
    private boolean fillBack() throws IOException {
        boolean widened = false;
        while (true) {
            long from = posTime - backSpan;
            boolean toStart = from <= startNanos || from > posTime;
            if (toStart) {
                from = Long.MIN_VALUE;
            }
            Iterator<LogEntry> it = entriesFrom(from);
            long lastTime = Long.MIN_VALUE;
            int rank = 0;
            int seen = 0;
            while (hasNext(it)) {
                LogEntry e = it.next();
                if (e.timeNanos() > posTime || (e.timeNanos() == posTime && rank(e, lastTime, rank) >= posRank)) {
                    break;
                }
                rank = rank(e, lastTime, rank);
                lastTime = e.timeNanos();
                back.add(new Ranked(e, lastTime, rank));
                rank++;
                seen++;
                if (back.size() > backWindow) {
                    back.remove(0);
                }
            }
            if (seen > backWindow) {
                backSpan = Math.max(1, backSpan / 2);
            }
            if (!back.isEmpty()) {
                if (widened) {
                    // the span grew to cross a quiet stretch; a busy stretch behind it must not
                    // pay for reading that far back on every later step
                    backSpan = FIRST_BACK_SPAN;
                }
                return true;
            }
            if (toStart) {
                return false;
            }
            widened = true;
            backSpan = backSpan > Long.MAX_VALUE / 4 ? Long.MAX_VALUE / 2 : backSpan * 4;
        }
    }

    /** The rank {@code e} will have: counting on within a time, from 0 at a new time. */
    private static int rank(LogEntry e, long lastTime, int nextRank) {
        return e.timeNanos() == lastTime ? nextRank : 0;
    }

    private Iterator<LogEntry> entriesFrom(long time) {
        return reader.entriesFrom(time);
    }

    private static boolean hasNext(Iterator<LogEntry> it) throws IOException {
        try {
            return it.hasNext();
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("cursor closed");
        }
    }

    @Override
    public void close() {
        closed = true;
        forward = null;
        back.clear();
    }
}
