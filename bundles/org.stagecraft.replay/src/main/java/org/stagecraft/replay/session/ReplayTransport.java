package org.stagecraft.replay.session;

import java.util.function.Supplier;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.play.Replayer;

/**
 * The transport of a {@link ReplaySession}: play, pause, step, seek and speed on whichever replayer is
 * on show (nothing happens before there is one), and the message published last, which the inspector
 * follows and a new reading of the file goes on after. Every move tells the view.
 */
public final class ReplayTransport {
    private final Supplier<@Nullable Replayer> replayer;
    private final Runnable moved;
    private volatile @Nullable LogMessage lastPublished;

    ReplayTransport(Supplier<@Nullable Replayer> replayer, Runnable moved) {
        this.replayer = replayer;
        this.moved = moved;
    }

    /** Moves the replay to {@code timeNanos} (a seek publishes the devices' replies from before it). */
    public void seek(long timeNanos) {
        Replayer r = replayer.get();
        if (r != null) {
            lastPublished = null;
            r.seek(timeNanos);
            moved.run();
        }
    }

    /** Moves the replay to {@code seconds} after the log's start. */
    public void seekSeconds(double seconds) {
        Replayer r = replayer.get();
        if (r != null) {
            seek(r.log().startNanos() + Math.round(seconds * 1e9));
        }
    }

    public void toStart() {
        Replayer r = replayer.get();
        if (r != null) {
            seek(r.log().startNanos());
        }
    }

    /** Shows the message before the one on show (publishes it again). */
    public void stepBack() {
        Replayer r = replayer.get();
        if (r != null) {
            lastPublished = r.stepBack();
            moved.run();
        }
    }

    /** Publishes the next message. */
    public void stepForward() {
        Replayer r = replayer.get();
        if (r != null) {
            lastPublished = r.stepForward();
            moved.run();
        }
    }

    public void playPause() {
        Replayer r = replayer.get();
        if (r != null) {
            if (r.playing()) {
                r.pause();
            } else {
                r.play();
            }
            moved.run();
        }
    }

    public void setSpeed(double speed) {
        Replayer r = replayer.get();
        if (r != null) {
            r.setSpeed(speed);
            moved.run();
        }
    }

    /** The next faster of the {@link Speeds#offered() offered speeds}. */
    public void faster() {
        Replayer r = replayer.get();
        if (r != null) {
            setSpeed(Speeds.faster(r.speed()));
        }
    }

    /** The next slower of the {@link Speeds#offered() offered speeds}. */
    public void slower() {
        Replayer r = replayer.get();
        if (r != null) {
            setSpeed(Speeds.slower(r.speed()));
        }
    }

    /** A message chosen (an inspector row): the replay moves there and publishes it, so views show that moment. */
    public void select(LogMessage m) {
        Replayer r = replayer.get();
        if (r != null) {
            r.seekTo(m);
            lastPublished = r.stepForward();
            moved.run();
        }
    }

    /** The message published last (by a step, a selection or play), null after a seek. Any thread. */
    public @Nullable LogMessage lastPublished() {
        return lastPublished;
    }

    /** What the replayer on show published, told by it or carried over from a replaced one. */
    void published(@Nullable LogMessage m) {
        lastPublished = m;
    }

    /** Where the replay is in {@code log} when there is no replayer yet: its start, or 0 before any log. */
    long position(@Nullable SessionLog log) {
        Replayer r = replayer.get();
        return r != null ? r.position() : log != null ? log.startNanos() : 0;
    }
}
