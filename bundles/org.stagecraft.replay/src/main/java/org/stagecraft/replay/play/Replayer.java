package org.stagecraft.replay.play;

import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.streams.StreamBus;

/**
 * Plays a {@link SessionLog} into a {@link StreamBus}: each message is published as
 * {@link LogMessage#toStreamMessage()} at its recorded time relative to the start of play, scaled
 * by the speed, so views work on replayed data exactly as on live data. Play runs on a thread of
 * its own; every method may be called from any thread.
 */
public final class Replayer implements AutoCloseable {
    public static final double MIN_SPEED = 0.1;
    public static final double MAX_SPEED = 16;

    public Replayer(SessionLog log, StreamBus bus, ReplayClock clock) {
        throw new UnsupportedOperationException("not built yet");
    }

    /** Plays from the current position at the current speed. */
    public void play() {
    }

    public void pause() {
    }

    public boolean playing() {
        return false;
    }

    /** @throws IllegalArgumentException outside {@link #MIN_SPEED}..{@link #MAX_SPEED} */
    public void setSpeed(double speed) {
    }

    public double speed() {
        return 1;
    }

    /** Moves the position to {@code timeNanos} (clamped to the log) without publishing. */
    public void seek(long timeNanos) {
    }

    /** Moves to {@code message} so that it is the next to publish. */
    public void seekTo(LogMessage message) {
    }

    /** Publishes the next message and moves past it; null at the end. Pauses play first. */
    public LogMessage stepForward() {
        return null;
    }

    /** Moves back before the previous message and publishes it again; null at the start. Pauses first. */
    public LogMessage stepBack() {
        return null;
    }

    /** Log time of the current position. */
    public long position() {
        return 0;
    }

    public void addListener(ReplayListener listener) {
    }

    public void removeListener(ReplayListener listener) {
    }

    /** Stops play; the log stays open (its owner closes it). */
    @Override
    public void close() {
    }
}
