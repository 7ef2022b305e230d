package org.stagecraft.replay.analysis;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import java.util.function.DoubleConsumer;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.streams.StreamKey;

/**
 * The Session Log timeline's model: how many messages each stream has in each of a fixed number of
 * time buckets between the log's start and end, plus where the problems (decode diagnostics,
 * unframed bytes) and the gaps (bytes the recorder missed) are. Memory is tracks x buckets whatever
 * the log's size; streams beyond {@link #MAX_TRACKS} share one "other streams" track. Filled by one
 * pass of a cursor ({@link #scan}), which can run in the background while the editor is already
 * usable: {@link #snapshot()} may be called at any time from any thread.
 */
public final class TimelineDensity {
    public static final int MAX_TRACKS = 64;
    static final String EVENTS = "connection events", OTHER = "other streams";

    /**
     * One track.
     *
     * @param key    the stream (null for the connection events and the overflow track)
     * @param label  what the timeline writes beside it
     * @param counts messages per bucket
     */
    public record Track(@Nullable StreamKey key, String label, int[] counts) {
        public long total() {
            long n = 0;
            for (int c : counts) {
                n += c;
            }
            return n;
        }

        public int max() {
            int m = 0;
            for (int c : counts) {
                m = Math.max(m, c);
            }
            return m;
        }
    }

    /** A consistent copy: tracks in display order, problem and gap marks per bucket, messages read. */
    public record Snapshot(long startNanos, long endNanos, int buckets, List<Track> tracks, int[] problems, int[] gaps,
            long messages) {
    }

    private final long start, end;
    private final int buckets;
    private final MessageColumns columns;
    private final Map<Object, Track> tracks = new LinkedHashMap<>();
    private final int[] problems, gaps;
    private long messages;

    public TimelineDensity(long startNanos, long endNanos, int buckets, MessageColumns columns) {
        if (buckets < 1) {
            throw new IllegalArgumentException("buckets " + buckets + " < 1");
        }
        this.start = startNanos;
        this.end = Math.max(endNanos, startNanos);
        this.buckets = buckets;
        this.columns = columns;
        this.problems = new int[buckets];
        this.gaps = new int[buckets];
    }

    /** Reads {@code log} once from its start; reports the fraction of its time read; stops early when cancelled. */
    public static TimelineDensity scan(SessionLog log, int buckets, MessageColumns columns, DoubleConsumer progress,
            BooleanSupplier cancelled) throws IOException {
        TimelineDensity d = new TimelineDensity(log.startNanos(), log.endNanos(), buckets, columns);
        d.fill(log, progress, cancelled);
        return d;
    }

    /** As {@link #scan} into this (created for the log's time range). */
    public void fill(SessionLog log, DoubleConsumer progress, BooleanSupplier cancelled) throws IOException {
        GapTracker gapTracker = new GapTracker();
        double span = Math.max(1, end - start);
        try (LogCursor c = log.cursor(start)) {
            long n = 0;
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                add(m, gapTracker.accept(m));
                if ((++n & 1023) == 0) {
                    if (cancelled.getAsBoolean()) {
                        return;
                    }
                    progress.accept(Math.min(1, (m.timeNanos() - start) / span));
                }
            }
        }
        progress.accept(1);
    }

    /** Bucket of log time {@code t} (clamped to the range). */
    public int bucketOf(long t) {
        if (t <= start) {
            return 0;
        }
        if (t >= end) {
            return buckets - 1;
        }
        return (int) Math.min(buckets - 1, (double) (t - start) * buckets / (end - start));
    }

    /** Log time at the start of bucket {@code i}. */
    public long bucketStart(int i) {
        return start + (long) ((double) (end - start) * i / buckets);
    }

    /** Counts one entry that was {@code gapBytes} after the end of the previous one of its stream. */
    public synchronized void add(LogMessage m, long gapBytes) {
        int b = bucketOf(m.timeNanos());
        messages++;
        if (m.isProblem()) {
            problems[b]++;
        }
        if (gapBytes > 0) {
            gaps[b]++;
        }
        if (m.kind() == LogMessage.Kind.DIAGNOSTIC) {
            return; // on the problem marks, not a stream of its own
        }
        Optional<StreamKey> key = MessageFilter.key(m);
        Object id = key.isPresent() ? key.get() : EVENTS;
        Track t = tracks.get(id);
        if (t == null) {
            if (tracks.size() >= MAX_TRACKS - 1 && id != EVENTS) {
                id = OTHER;
                t = tracks.get(OTHER);
            }
            if (t == null) {
                t = new Track(id instanceof StreamKey k ? k : null, label(m, id), new int[buckets]);
                tracks.put(id, t);
            }
        }
        t.counts()[b]++;
    }

    private String label(LogMessage m, Object id) {
        if (id == EVENTS || id == OTHER) {
            return (String) id;
        }
        return columns.device(m) + " " + columns.type(m) + " " + columns.subtype(m) + " (#" + m.connection().id() + " "
                + columns.direction(m) + ")";
    }

    public synchronized Snapshot snapshot() {
        List<Track> list = new ArrayList<>();
        for (Track t : tracks.values()) {
            list.add(new Track(t.key(), t.label(), t.counts().clone()));
        }
        list.sort(ORDER);
        return new Snapshot(start, end, buckets, List.copyOf(list), problems.clone(), gaps.clone(), messages);
    }

    /** Streams by device, index, message type, subtype, then source; events and overflow last. */
    private static final Comparator<Track> ORDER = Comparator
            .comparing((Track t) -> t.key() == null ? 1 : 0)
            .thenComparing(t -> t.key() == null ? 0 : t.key().deviceType())
            .thenComparing(t -> t.key() == null ? 0 : t.key().index())
            .thenComparing(t -> t.key() == null ? 0 : t.key().messageType())
            .thenComparing(t -> t.key() == null ? 0 : t.key().subtype())
            .thenComparing(t -> t.key() == null ? t.label() : t.key().source());
}
