package org.stagecraft.replay.session;

import org.stagecraft.replay.play.Replayer;

/**
 * What a {@link ReplaySession} tells whoever shows it (the Session Log editor). Only
 * {@link #logShown} comes on the owner thread; the others come from any thread (the replay thread,
 * the timeline pass) and must only ask for an update, never wait.
 */
public interface SessionView {
    /** A log is in place, first opened or read again: show its range, marks and inspector. Owner thread. */
    void logShown(SharedLog log, Replayer replayer);

    /** What {@link ReplaySession#statusText()} says may have changed. Any thread. */
    void statusChanged();

    /** The replay moved, or started or stopped playing. Any thread. */
    void replayMoved();

    /** The timeline pass filled in more of {@link ReplaySession#density()}. Any thread. */
    void timelineFilled();

    /** Something went wrong that the user need not be told at once but a log should keep. Any thread. */
    void warning(String text);
}
