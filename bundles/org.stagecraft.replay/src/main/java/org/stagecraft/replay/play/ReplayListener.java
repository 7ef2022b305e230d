package org.stagecraft.replay.play;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.log.LogMessage;

/** Told what a {@link Replayer} does; called on the replay thread or the caller's, keep it short. */
public interface ReplayListener {

    /**
     * The replay position changed (played, stepped or sought).
     *
     * @param timeNanos log time of the position
     * @param last      the message last published, or null after a seek
     */
    void moved(long timeNanos, @Nullable LogMessage last);

    /** Play/pause or speed changed, or the end of the log was reached (then {@code playing} is false). */
    void stateChanged(boolean playing, double speed);
}
