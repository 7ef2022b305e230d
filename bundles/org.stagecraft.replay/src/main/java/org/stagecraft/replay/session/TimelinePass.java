package org.stagecraft.replay.session;

import java.io.IOException;
import java.util.function.Consumer;
import java.util.function.LongConsumer;

import org.stagecraft.replay.analysis.MessageColumns;
import org.stagecraft.replay.analysis.TimelineDensity;
import org.stagecraft.replay.log.SessionLog;

/**
 * One background pass over a log filling its timeline ({@link TimelineDensity}: counts per stream per
 * bucket). The pass holds the log ({@link SharedLog}) while it reads, so a reload does not close it
 * under the pass; a replaced pass is cancelled and ends soon by itself.
 */
final class TimelinePass {
    private final TimelineDensity density;
    private final SessionThreads.Work work;
    private volatile boolean ended;

    /**
     * Starts the pass. {@code filled} is told (any thread) as the buckets fill and once at the end,
     * {@code cost} what the whole pass took, {@code warning} why it stopped early.
     */
    TimelinePass(SharedLog s, String name, int buckets, MessageColumns columns, SessionThreads threads, Runnable filled,
            LongConsumer cost, Consumer<String> warning) {
        SessionLog l = s.log();
        density = new TimelineDensity(l.startNanos(), l.endNanos(), buckets, columns);
        work = threads.background(name, false, progress -> {
            if (!s.acquire()) {
                ended = true; // replaced and closed before the pass began
                return;
            }
            long started = System.nanoTime();
            try {
                density.fill(l, f -> {
                    progress.done(f);
                    filled.run();
                }, progress::cancelled);
            } catch (IOException | RuntimeException e) {
                warning.accept("timeline of " + l.path() + " stopped: " + e.getMessage());
            } finally {
                s.release();
            }
            cost.accept(System.nanoTime() - started);
            ended = true;
            filled.run();
        });
    }

    TimelineDensity density() {
        return density;
    }

    /** Whether the pass has ended (read the whole log, stopped on an error, or was cancelled). */
    boolean ended() {
        return ended;
    }

    void cancel() {
        work.cancel();
    }
}
