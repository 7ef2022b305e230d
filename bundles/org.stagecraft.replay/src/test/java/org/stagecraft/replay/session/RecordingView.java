package org.stagecraft.replay.session;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;

import org.stagecraft.replay.play.Replayer;

/** A session's view in a plain test: records what it was told. */
final class RecordingView implements SessionView {
    final List<SharedLog> shown = new CopyOnWriteArrayList<>();
    final List<Replayer> replayers = new CopyOnWriteArrayList<>();
    final List<String> warnings = new CopyOnWriteArrayList<>();
    final AtomicInteger statusChanges = new AtomicInteger();
    final AtomicInteger moves = new AtomicInteger();
    final AtomicInteger fills = new AtomicInteger();

    @Override
    public void logShown(SharedLog log, Replayer replayer) {
        shown.add(log);
        replayers.add(replayer);
    }

    @Override
    public void statusChanged() {
        statusChanges.incrementAndGet();
    }

    @Override
    public void replayMoved() {
        moves.incrementAndGet();
    }

    @Override
    public void timelineFilled() {
        fills.incrementAndGet();
    }

    @Override
    public void warning(String text) {
        warnings.add(text);
    }
}
