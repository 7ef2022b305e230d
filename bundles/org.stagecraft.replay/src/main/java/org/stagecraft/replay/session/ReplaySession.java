package org.stagecraft.replay.session;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.RejectedExecutionException;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.analysis.MessageColumns;
import org.stagecraft.replay.analysis.TimelineDensity;
import org.stagecraft.replay.log.HoldMarks;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.play.ReplayListener;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.streams.StreamBus;

/**
 * A log file open for replay, as the Session Log editor shows it, without any UI: reads the file in
 * the background, replays it into a bus, swaps in a new reading of the file (Reload, or a log still
 * being written that grew) without losing the replay's place, follows a growing log at a bounded
 * cost, runs the timeline pass ({@link TimelinePass}), and says in one status text what is on show and
 * what went wrong. Its {@link #transport()} plays, steps and seeks the replayer on show.
 *
 * <p>The session belongs to its owner thread ({@link SessionThreads}): everything here is called
 * there unless it says otherwise. The log, its replayer and what was published last are readable from
 * any thread. Nothing here waits for background work: work no longer wanted is cancelled and ends by
 * itself, and a log that is replaced is closed once its last reader lets it go ({@link SharedLog}).
 */
public final class ReplaySession implements AutoCloseable {
    /** Timeline resolution: buckets across the whole log, whatever its length. */
    public static final int BUCKETS = 600;
    /** How often a log still being written is looked at, at the most. */
    public static final int FOLLOW_MILLIS = 2000;
    /** The next look at a growing log waits this many times what the last one cost. */
    public static final int FOLLOW_FACTOR = 4;

    private final Path file;
    private final MessageColumns columns;
    private final StreamBus bus;
    private final SessionThreads threads;
    private final FollowPace pace;
    private final SessionView view;
    private final ReplayTransport transport;

    /** The log on show with its readers' hold on it, and its replayer: replaced together, on the owner thread. */
    private volatile @Nullable SharedLog shared;
    private volatile @Nullable Replayer replayer;
    private volatile HoldMarks holds = HoldMarks.none();
    private volatile @Nullable TimelinePass pass;
    /** What stopped play, told by the replayer; cleared when play starts again. */
    private volatile @Nullable String playFailure;
    /** Why the file could not be opened at all; why reading it again failed (the previous reading stays). */
    private volatile @Nullable String openError, reopenError;
    /** The reading under way (owner thread), and the number of the latest one asked for. */
    private SessionThreads.@Nullable Work reading;
    private long generation;
    private boolean closed;
    /** Following a log still being written: its size when last read, when that look began, whether it grows. */
    private long followedSize = -1;
    private long lastLookNanos;
    private volatile boolean growing;

    /**
     * A session on {@code file}, replaying into {@code bus} (the caller's: it outlives readings of the
     * file), decoding with {@code columns}' codecs. Nothing is read before {@link #open()}.
     */
    public ReplaySession(Path file, MessageColumns columns, StreamBus bus, SessionThreads threads, FollowPace pace,
            SessionView view) {
        this.file = Objects.requireNonNull(file);
        this.columns = columns;
        this.bus = bus;
        this.threads = threads;
        this.pace = pace;
        this.view = view;
        this.transport = new ReplayTransport(() -> replayer, view::replayMoved);
    }

    // --- reading the file ----------------------------------------------------------------------

    /** Reads the file in the background; the log appears once read ({@link SessionView#logShown}). */
    public void open() {
        startReading(false);
    }

    /**
     * Reads the file again in the background, keeping the replay's place (a growing log shows what was
     * added); returns at once, and the log on show stays usable until the new reading replaces it.
     */
    public void reload() {
        startReading(false);
    }

    /**
     * A spy log without its summary is one the spy is probably still writing: while it grows it is read
     * again, keeping the position and play. A look costs a reopen (a scan of the file) and a timeline
     * pass over it, so the next look waits for the pass to end and for at least the {@link FollowPace}'s
     * delay. Call this periodically: it says in how many milliseconds to call it again, or -1 when
     * following has ended (the log is complete: the spy closed it; or the session is closed).
     */
    public long follow() {
        if (closed) {
            return -1;
        }
        SessionLog l = log();
        if (l != null && l.complete()) {
            growing = false;
            view.statusChanged();
            return -1; // whole: nothing more will come
        }
        long next = pace.minMillis();
        TimelinePass p = pass;
        if (reading == null && (p == null || p.ended())) {
            long waited = (System.nanoTime() - lastLookNanos) / 1_000_000;
            long due = pace.delayMillis();
            if (waited < due) {
                next = due - waited;
            } else {
                long size = fileSize();
                if (size >= 0 && size != followedSize) {
                    growing = true;
                    startReading(true);
                }
            }
        }
        return Math.max(1, next);
    }

    private void startReading(boolean followed) {
        if (closed) {
            return;
        }
        long g = ++generation;
        if (reading != null) {
            reading.cancel(); // superseded: its result is closed unseen
        }
        followedSize = fileSize();
        lastLookNanos = System.nanoTime();
        // a first open (perhaps a long import) shows its progress; looks at a growing log do not
        reading = threads.background("Reading " + file.getFileName(), followed, progress -> {
            OpenedLog o = OpenedLog.read(file, columns.registry(), bus,
                    (log, e) -> view.warning("closing " + log.path() + ": " + e));
            try {
                threads.onOwner(() -> swapIn(g, o));
            } catch (RejectedExecutionException gone) {
                discard(o); // the owner is gone
            }
        });
        view.statusChanged();
    }

    /**
     * Puts a fresh reading in place of the log shown. The replay goes on where it was, at the same speed
     * and playing if it played: just after the message last published (so nothing is published again),
     * or at the same time after a seek. The old log is closed once its readers are done.
     */
    private void swapIn(long g, OpenedLog o) {
        if (closed || g != generation) {
            discard(o); // superseded, or nobody left to show it
            return;
        }
        reading = null;
        pace.reopened(o.costNanos());
        Exception error = o.error();
        if (error != null) {
            String why = Failures.describe(error);
            view.warning("cannot " + (log() == null ? "open " : "read again ") + file + ": " + why);
            if (log() == null) {
                openError = o.error().getMessage() == null ? why : o.error().getMessage();
            } else {
                reopenError = why;
            }
            view.statusChanged();
            return;
        }
        Replayer old = replayer;
        SharedLog oldShared = shared;
        Replayer r = Objects.requireNonNull(o.replayer()); // read without an error: both are there
        boolean play = old != null && carryOn(old, r);
        r.addListener(new Listener(r));
        SharedLog s = Objects.requireNonNull(o.shared());
        SessionLog l = s.log();
        holds = holdMarks(l);
        shared = s;
        replayer = r;
        openError = null;
        reopenError = null;
        playFailure = null;
        if (play) {
            r.play();
        }
        TimelinePass before = pass;
        if (before != null) {
            before.cancel(); // the old pass ends soon and lets go of the old log
        }
        pass = new TimelinePass(s, "Reading the streams of " + file.getFileName(), BUCKETS, columns, threads,
                view::timelineFilled, pace::timelinePassed, view::warning);
        retire(old, oldShared);
        if (l.complete()) {
            growing = false; // the spy closed it while we looked
        }
        view.logShown(s, r);
        view.statusChanged();
        view.replayMoved();
    }

    /**
     * The new replayer takes over from the old: same speed, just past the same message. Says whether
     * the old one was playing (the new one plays once it is in place).
     */
    private boolean carryOn(Replayer old, Replayer r) {
        boolean playing = old.playing();
        old.pause(); // nothing more from the old log: what it published last is final
        r.setSpeed(old.speed());
        LogMessage last = old.lastPublished();
        try {
            if (last != null) {
                r.seekAfter(last); // the same file: the reopened log has the same message at the same place
                transport.published(last);
                return playing;
            }
        } catch (RuntimeException e) {
            view.warning(file + " read again lacks the message last shown; going on at its time: " + e);
        }
        r.seek(old.position());
        return playing;
    }

    /** The log's robot holds (none if it has none or they cannot be read: the rest of the log still shows). */
    private HoldMarks holdMarks(SessionLog l) {
        try {
            return new HoldMarks(l.holdEntries(), l.endNanos());
        } catch (IOException | RuntimeException e) {
            view.warning("robot holds of " + l.path() + " not shown: " + e.getMessage());
            return HoldMarks.none();
        }
    }

    private void discard(OpenedLog o) {
        retire(o.replayer(), o.shared());
    }

    /**
     * Stops a replaced replayer and lets its log go, in the background: stopping waits for the play
     * thread, and the log closes when its last reader (timeline pass, inspector, plot) is done.
     */
    private void retire(@Nullable Replayer r, @Nullable SharedLog s) {
        if (r == null && s == null) {
            return;
        }
        threads.background("Closing a replaced Session Log", true, progress -> {
            if (r != null) {
                r.close();
            }
            if (s != null) {
                s.retire();
            }
        });
    }

    private long fileSize() {
        try {
            return Files.size(file);
        } catch (IOException e) {
            return -1;
        }
    }

    /** Tells the session what its replayer does; a replaced replayer's late news is ignored. Replay thread. */
    private final class Listener implements ReplayListener {
        private final Replayer r;

        Listener(Replayer r) {
            this.r = r;
        }

        @Override
        public void moved(long timeNanos, @Nullable LogMessage last) {
            if (r == replayer) {
                transport.published(last);
                view.replayMoved();
            }
        }

        @Override
        public void stateChanged(boolean playing, double speed) {
            if (r != replayer) {
                return;
            }
            Exception failure = playing ? null : r.failure();
            String before = playFailure;
            if (failure != null) {
                playFailure = Failures.describe(failure);
            } else if (playing) {
                playFailure = null; // played again: the failure is history
            }
            if (!Objects.equals(before, playFailure)) {
                view.statusChanged();
            }
            view.replayMoved();
        }
    }

    // --- what is on show ----------------------------------------------------------------------------

    public Path file() {
        return file;
    }

    /** The log on show, or null while the file is first read or when it could not be opened at all. Any thread. */
    public @Nullable SessionLog log() {
        SharedLog s = shared;
        return s == null ? null : s.log();
    }

    /** The log on show with its readers' hold on it: read it only between acquire and release. Any thread. */
    public @Nullable SharedLog sharedLog() {
        return shared;
    }

    /** The replayer of the log on show, or null. Any thread. */
    public @Nullable Replayer replayer() {
        return replayer;
    }

    /** Play, pause, step, seek and speed on the replayer on show. */
    public ReplayTransport transport() {
        return transport;
    }

    /** Where the replay is, or the log's start, or 0 before any log. Any thread. */
    public long position() {
        return transport.position(log());
    }

    /** The log's robot holds. Any thread. */
    public HoldMarks holds() {
        return holds;
    }

    /** The timeline of the log on show, filling in while its pass runs; null before any log. Any thread. */
    public @Nullable TimelineDensity density() {
        TimelinePass p = pass;
        return p == null ? null : p.density();
    }

    /** Whether the pass that fills the timeline of the log on show has ended. Any thread. */
    public boolean timelineComplete() {
        TimelinePass p = pass;
        return p != null && p.ended();
    }

    /** Whether the file is being read (opened, or opened again) in the background. */
    public boolean reading() {
        return reading != null;
    }

    /** Whether the session is following a log that is still being written. */
    public boolean following() {
        return growing;
    }

    /**
     * What the status line says: the log, whether it is being read (again), where a damaged one
     * stopped, and what stopped play.
     */
    public String statusText() {
        SessionLog l = log();
        if (l == null) {
            return openError == null ? "Reading " + file + "\u2026" : "Cannot open " + file + ": " + openError;
        }
        StringBuilder s = new StringBuilder();
        s.append(switch (l.format()) {
            case SPY_LOG -> "Spy log";
            case PLAYER_TRACE -> "Recorded trace";
            case WRITELOG -> "Player writelog";
        });
        s.append(String.format(Locale.ROOT, ", %.3f s, %,d messages, %d connection%s", (l.endNanos() - l.startNanos()) / 1e9,
                l.messageCount(), l.connections().size(), l.connections().size() == 1 ? "" : "s"));
        long size = fileSize();
        if (size >= 0) {
            s.append(String.format(Locale.ROOT, ", %,d bytes", size)); // only for information
        }
        if (growing) {
            s.append(" — still being written: read again as it grows");
        }
        if (reading != null) {
            s.append(" — reading\u2026");
        }
        if (reopenError != null) {
            s.append("\nCannot read it again: ").append(reopenError);
        }
        String failure = playFailure;
        if (failure != null) {
            s.append("\nReplay stopped: ").append(failure);
        }
        List<LogProblem> problems = l.problems();
        for (LogProblem p : problems) {
            s.append("\n").append(p.where()).append(String.format(Locale.ROOT, " (%.3f s): ", (p.timeNanos() - l.startNanos()) / 1e9))
                    .append(p.text());
        }
        return s.toString();
    }

    /**
     * Whether the status tells of something wrong: the file cannot be read, play stopped, the log is
     * damaged. A log still being written lacks its summary by nature: that alone is no reason for alarm.
     */
    public boolean alarming() {
        SessionLog l = log();
        return openError != null || reopenError != null || playFailure != null
                || (l != null && !l.problems().isEmpty() && !(growing && l.problems().size() == 1));
    }

    /**
     * Ends the session: readings and the timeline pass are cancelled and end by themselves, the replay
     * stops and the log closes once its readers are done. Nothing here waits. The bus stays the caller's.
     */
    @Override
    public void close() {
        closed = true;
        generation++;
        if (reading != null) {
            reading.cancel();
            reading = null;
        }
        TimelinePass p = pass;
        if (p != null) {
            p.cancel();
        }
        retire(replayer, shared);
        replayer = null;
        shared = null;
    }
}
