package org.stagecraft.replay.analysis;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;

/**
 * The part of a log the packet inspector holds: up to {@code before} filtered entries before an
 * anchor and {@code after} from it on, read with a cursor, so the inspector's memory does not grow
 * with the log. A sparse filter may have to skip many entries; at most {@code scanLimit} are read
 * on each side, and the window says when it stopped for that rather than at an end of the log.
 *
 * @param rows        the entries in log order
 * @param anchorIndex index of the first row at or after the anchor ({@code rows.size()} when none)
 * @param atStart     no earlier entry passes the filter (the start of the log was reached)
 * @param atEnd       no later entry passes the filter
 */
public record MessageWindow(List<InspectorRow> rows, int anchorIndex, boolean atStart, boolean atEnd) {

    public MessageWindow {
        rows = List.copyOf(rows);
    }

    /** The window around log time {@code anchorNanos}. */
    public static MessageWindow around(SessionLog log, MessageFilter filter, long anchorNanos, int before, int after,
            int scanLimit) throws IOException {
        try (LogCursor c = log.cursor(anchorNanos)) {
            return withHolds(read(c, filter, before, after, scanLimit), log.holdRows(), filter);
        }
    }

    /** The window with {@code anchor} (an entry of the log) as the first row at the anchor. */
    public static MessageWindow around(SessionLog log, MessageFilter filter, LogMessage anchor, int before, int after,
            int scanLimit) throws IOException {
        if (anchor.kind() == LogMessage.Kind.HOLD) {
            return around(log, filter, anchor.timeNanos(), before, after, scanLimit); // a hold's row is no cursor entry
        }
        try (LogCursor c = log.cursor(anchor.timeNanos())) {
            c.seekTo(anchor);
            return withHolds(read(c, filter, before, after, scanLimit), log.holdRows(), filter);
        }
    }

    /**
     * The window with the rows of what the robot hold did ({@link LogMessage.Kind#HOLD}) that lie within
     * its time span (to the log's start or end where it reaches them) merged in by time, after the
     * messages of the same time; the filter applies to them as to the messages.
     */
    static MessageWindow withHolds(MessageWindow w, List<LogMessage> holds, MessageFilter filter) {
        if (holds.isEmpty() || w.rows.isEmpty() && !(w.atStart && w.atEnd)) {
            return w;
        }
        long from = w.atStart ? Long.MIN_VALUE : w.rows.get(0).message().timeNanos();
        long to = w.atEnd ? Long.MAX_VALUE : w.rows.get(w.rows.size() - 1).message().timeNanos();
        List<InspectorRow> merged = new ArrayList<>(w.rows.size() + 16);
        int anchor = w.anchorIndex, newAnchor = -1, i = 0, h = 0;
        while (i < w.rows.size() || h < holds.size()) {
            if (h == holds.size() || i < w.rows.size() && w.rows.get(i).message().timeNanos() <= holds.get(h).timeNanos()) {
                if (i == anchor) {
                    newAnchor = merged.size();
                }
                merged.add(w.rows.get(i++));
            } else {
                LogMessage m = holds.get(h++);
                if (m.timeNanos() >= from && m.timeNanos() <= to && filter.matches(m)) {
                    merged.add(new InspectorRow(m, 0));
                }
            }
        }
        return new MessageWindow(merged, newAnchor < 0 ? merged.size() : newAnchor, w.atStart, w.atEnd);
    }

    public boolean isEmpty() {
        return rows.isEmpty();
    }

    /** Index of the row holding {@code m} (same place in the log), or -1. */
    public int indexOf(@Nullable LogMessage m) {
        if (m == null) {
            return -1;
        }
        for (int i = 0; i < rows.size(); i++) {
            if (rows.get(i).message().samePlace(m)) {
                return i;
            }
        }
        return -1;
    }

    /** Whether log time {@code t} lies between the first and the last row. */
    public boolean covers(long t) {
        return !rows.isEmpty() && t >= rows.get(0).message().timeNanos()
                && t <= rows.get(rows.size() - 1).message().timeNanos();
    }

    /**
     * Walks back to find where the window starts, then reads forward once from there: the forward
     * pass sees every entry in order, which the gap marks need.
     */
    private static MessageWindow read(LogCursor c, MessageFilter filter, int before, int after, int scanLimit)
            throws IOException {
        LogMessage anchor = c.next();
        if (anchor != null) {
            c.previous();
        }
        int matched = 0, scanned = 0;
        LogMessage start = null;
        boolean atStart = false;
        if (before == 0) {
            if (c.previous() == null) {
                atStart = true;
            } else {
                c.next();
            }
        }
        while (matched < before) {
            LogMessage m = c.previous();
            if (m == null) {
                atStart = true;
                break;
            }
            start = m;
            if (filter.matches(m)) {
                matched++;
            }
            if (++scanned >= scanLimit) {
                break;
            }
        }
        if (start != null) {
            c.seekTo(start);
        } else if (anchor != null) {
            c.seekTo(anchor);
        }
        List<InspectorRow> rows = new ArrayList<>();
        GapTracker gaps = new GapTracker();
        int anchorIndex = -1;
        boolean reachedAnchor = start == null;
        int afterMatched = 0, afterScanned = 0;
        boolean atEnd = false;
        while (true) {
            LogMessage m = c.next();
            if (m == null) {
                atEnd = true;
                break;
            }
            if (!reachedAnchor && anchor != null && m.samePlace(anchor)) {
                reachedAnchor = true;
            }
            long gap = gaps.accept(m);
            boolean match = filter.matches(m);
            if (reachedAnchor) {
                if (afterMatched >= after) {
                    break;
                }
                afterScanned++;
                if (match) {
                    if (anchorIndex < 0) {
                        anchorIndex = rows.size();
                    }
                    afterMatched++;
                }
            }
            if (match) {
                rows.add(new InspectorRow(m, gap));
            }
            if (reachedAnchor && afterScanned >= scanLimit) {
                break;
            }
        }
        return new MessageWindow(rows, anchorIndex < 0 ? rows.size() : anchorIndex, atStart, atEnd);
    }
}
