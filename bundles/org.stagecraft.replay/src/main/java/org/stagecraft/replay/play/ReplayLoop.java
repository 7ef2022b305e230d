package org.stagecraft.replay.play;

import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.log.LogMessage;

/**
 * Plays a {@link Replayer} over and over: when play stops at the end of the log, it starts again
 * from the start, so a recorded session runs in the views like a robot that never stops
 * (demonstrations, screenshots). A pause before the end, or a failure, stops it as it stops any
 * replay; a pass that published nothing is not repeated (it would spin).
 */
public final class ReplayLoop implements ReplayListener {
    private final Replayer replayer;
    private final AtomicInteger passes = new AtomicInteger();
    /** Whether the current pass published anything; only such a pass is worth repeating. */
    private volatile boolean publishedThisPass;

    private ReplayLoop(Replayer replayer) {
        this.replayer = replayer;
    }

    /** Starts {@code replayer} playing from where it is, and again from the start at every end. */
    public static ReplayLoop start(Replayer replayer) {
        ReplayLoop loop = new ReplayLoop(replayer);
        replayer.addListener(loop);
        replayer.play();
        return loop;
    }

    /** How many times play has reached the end of the log and started again. */
    public int restarts() {
        return passes.get();
    }

    @Override
    public void moved(long timeNanos, @Nullable LogMessage last) {
        if (last != null) {
            publishedThisPass = true;
        }
    }

    @Override
    public void stateChanged(boolean playing, double speed) {
        if (playing || !publishedThisPass || replayer.failure() != null
                || replayer.position() < replayer.log().endNanos()) {
            return; // paused by someone, failed, or nothing to repeat: not the end of a pass
        }
        publishedThisPass = false;
        passes.incrementAndGet();
        replayer.seek(replayer.log().startNanos());
        replayer.play();
    }
}
