package org.stagecraft.replay.session;

import java.util.concurrent.RejectedExecutionException;

/**
 * Where a {@link ReplaySession}'s work runs. The session belongs to one thread, its owner (the
 * workbench's UI thread): every method of the session not marked otherwise is called there, and
 * background results come back there. Reading a file and the timeline pass run in the background
 * (Eclipse jobs in the workbench, with progress; an executor in the plain tests).
 */
public interface SessionThreads {
    /**
     * Starts {@code task} off the owner thread. {@code quiet} work (looking at a growing log again,
     * closing a replaced one) shows the user no progress.
     */
    Work background(String name, boolean quiet, Task task);

    /**
     * Runs {@code r} on the owner thread later, never before this call returns.
     *
     * @throws RejectedExecutionException when the owner is gone (the workbench is closing)
     */
    void onOwner(Runnable r);

    /** Work done in the background. */
    interface Task {
        void run(Progress progress);
    }

    /** What background work is told and tells. */
    interface Progress {
        /** Whether the work is no longer wanted: it should end soon. */
        boolean cancelled();

        /** How much is done, 0 to 1. */
        void done(double fraction);
    }

    /** Background work under way. */
    interface Work {
        /** Asks the work to end (it ends by itself; nothing waits for it). */
        void cancel();
    }
}
