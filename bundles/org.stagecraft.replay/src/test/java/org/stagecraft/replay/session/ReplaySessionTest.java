package org.stagecraft.replay.session;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Arrays;
import java.util.concurrent.LinkedBlockingQueue;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.replay.analysis.MessageColumns;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.Logs;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * The Session Log editor's model without its UI, on the shared single-robot recording: reading in the
 * background, reading again without losing the replay's place, following a log still being written,
 * the timeline pass, the transport and the status text.
 */
@Timeout(120)
class ReplaySessionTest {
    private static final long WAIT = 60_000;

    @TempDir
    Path tmp;

    private final StreamBus bus = new StreamBus();
    private final TestThreads threads = new TestThreads();
    private final RecordingView view = new RecordingView();
    private ReplaySession session;

    @AfterEach
    void close() {
        if (session != null) {
            session.close();
        }
        threads.close();
        bus.close();
    }

    private ReplaySession session(Path file, FollowPace pace) {
        session = new ReplaySession(file, new MessageColumns(CodecRegistry.standard()), bus, threads, pace, view);
        return session;
    }

    private ReplaySession opened(Path file, FollowPace pace) throws InterruptedException {
        ReplaySession s = session(file, pace);
        s.open();
        threads.runUntil(() -> !s.reading(), WAIT, "the first reading of " + file);
        return s;
    }

    private Path spyLog(String name) throws IOException {
        return Logs.spyLog(Logs.trace(Logs.GT), tmp.resolve(name), 16 << 10);
    }

    private static FollowPace everyLook() {
        return new FollowPace(0, 0);
    }

    @Test
    void aLogIsReadInTheBackgroundThenShownWithItsTimeline() throws Exception {
        Path trace = Logs.trace(Logs.GT);
        ReplaySession s = session(trace, everyLook());
        s.open();
        assertTrue(s.reading(), "read in the background");
        assertNull(s.log());
        assertEquals("Reading " + trace + "\u2026", s.statusText());
        assertEquals(0, s.position(), "no position before a log");

        threads.runUntil(() -> !s.reading(), WAIT, "the reading");
        SessionLog log = s.log();
        assertNotNull(log, s.statusText());
        assertEquals(LogFormat.PLAYER_TRACE, log.format());
        assertEquals(1, view.shown.size(), "shown once");
        assertSame(s.sharedLog(), view.shown.get(0));
        assertSame(s.replayer(), view.replayers.get(0));
        assertEquals(log.startNanos(), s.position());
        assertTrue(s.statusText().startsWith("Recorded trace, "), s.statusText());
        assertTrue(s.statusText().contains(String.format(java.util.Locale.ROOT, "%,d messages", log.messageCount())), s.statusText());
        assertFalse(s.alarming(), s.statusText());

        threads.runUntil(s::timelineComplete, WAIT, "the timeline pass");
        assertEquals(Logs.all(log).size(), s.density().snapshot().messages(), "the pass counted every message of the log");
        assertEquals(ReplaySession.BUCKETS, s.density().snapshot().buckets());
        assertTrue(view.fills.get() > 0, "the view was told the timeline filled");
    }

    @Test
    void aFileThatIsNoLogSaysWhyInRed() throws Exception {
        Path junk = Files.writeString(tmp.resolve("junk.mcap"), "this is not a spy log\n");
        ReplaySession s = opened(junk, everyLook());
        assertNull(s.log());
        assertNull(s.replayer());
        assertTrue(s.statusText().startsWith("Cannot open " + junk + ": "), s.statusText());
        assertTrue(s.alarming());
        assertTrue(view.shown.isEmpty());
        assertTrue(view.warnings.stream().anyMatch(w -> w.startsWith("cannot open " + junk)), view.warnings.toString());
        s.transport().stepForward(); // the transport does nothing without a log
        s.transport().playPause();
        assertNull(s.replayer());
    }

    @Test
    void readingAgainGoesOnJustAfterTheMessageLastPublishedAndClosesTheOldLog() throws Exception {
        ReplaySession s = opened(spyLog("reloaded.mcap"), everyLook());
        s.transport().seek(s.log().startNanos() + 5_000_000_000L);
        LogMessage last = null;
        for (int i = 0; i < 100 && (last == null || last.toStreamMessage().isEmpty()); i++) {
            s.transport().stepForward();
            last = s.transport().lastPublished();
        }
        assertNotNull(last);
        Replayer oldReplayer = s.replayer();
        SharedLog oldShared = s.sharedLog();
        s.transport().setSpeed(4);

        s.reload();
        assertTrue(s.reading());
        assertTrue(s.statusText().contains(" — reading\u2026"), s.statusText());
        assertSame(oldReplayer, s.replayer(), "the old reading stays usable until the new one is in place");
        threads.runUntil(() -> !s.reading(), WAIT, "the reading again");

        assertNotSame(oldReplayer, s.replayer());
        assertEquals(2, view.shown.size());
        assertTrue(last.samePlace(s.replayer().lastPublished()), "the new replayer counts the message as published");
        assertTrue(last.samePlace(s.transport().lastPublished()));
        assertEquals(4, s.replayer().speed(), 1e-9, "the speed carries over");
        assertFalse(s.replayer().playing());
        assertFalse(s.statusText().contains("reading\u2026"), s.statusText());
        threads.runUntil(oldShared::isClosed, WAIT, "the replaced log to be closed");

        LogMessage expected = publishedAfter(s.log(), last);
        LinkedBlockingQueue<StreamMessage> received = new LinkedBlockingQueue<>();
        try (Subscription sub = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 12), received::add)) {
            LogMessage stepped = null;
            for (int i = 0; i < 100 && (stepped == null || stepped.toStreamMessage().isEmpty()); i++) {
                s.transport().stepForward();
                stepped = s.transport().lastPublished();
            }
            assertTrue(expected.samePlace(stepped), "the next step publishes the message after it: " + stepped);
        }
    }

    @Test
    void playCarriesOverToTheNewReading() throws Exception {
        ReplaySession s = opened(spyLog("playing.mcap"), everyLook());
        s.transport().setSpeed(0.1); // slow: the log does not end while it is read again
        s.transport().playPause();
        assertTrue(s.replayer().playing());
        Replayer old = s.replayer();
        s.reload();
        threads.runUntil(() -> !s.reading(), WAIT, "the reading again");
        assertNotSame(old, s.replayer());
        assertFalse(old.playing(), "the old replayer stopped");
        assertTrue(s.replayer().playing(), "the new one plays on");
        assertEquals(0.1, s.replayer().speed(), 1e-9);
        s.transport().playPause();
        assertFalse(s.replayer().playing());
    }

    @Test
    void aNewerReadingSupersedesOneUnderWay() throws Exception {
        ReplaySession s = session(spyLog("twice.mcap"), everyLook());
        s.open();
        s.reload(); // before the first reading is in: it is cancelled and its result closed unseen
        assertTrue(threads.cancelled.get() >= 1, "the first reading was cancelled");
        threads.runUntil(() -> !s.reading() && s.timelineComplete(), WAIT, "the second reading");
        assertEquals(1, view.shown.size(), "only the newest reading is shown");
        assertSame(s.sharedLog(), view.shown.get(0));
    }

    @Test
    void aLogStillBeingWrittenIsFollowedUntilItIsComplete() throws Exception {
        Path whole = spyLog("whole.mcap");
        byte[] all = Files.readAllBytes(whole);
        Path growing = tmp.resolve("growing.mcap");
        Files.write(growing, Arrays.copyOf(all, all.length / 3)); // what a running spy has on disk so far
        ReplaySession s = opened(growing, everyLook());
        SessionLog first = s.log();
        assertFalse(first.complete(), "no summary yet");
        long firstCount = first.messageCount();
        threads.runUntil(s::timelineComplete, WAIT, "the first timeline pass");

        assertTrue(s.follow() > 0);
        assertFalse(s.reading(), "nothing grew: no reading");

        Files.write(growing, Arrays.copyOf(all, all.length * 2 / 3));
        assertTrue(s.follow() > 0, "still following");
        assertTrue(s.reading(), "the grown file is read again");
        assertTrue(s.following());
        assertTrue(s.statusText().contains("still being written"), s.statusText());
        threads.runUntil(() -> !s.reading(), WAIT, "the grown log");
        assertEquals(1, s.log().problems().size(), s.statusText());
        assertFalse(s.alarming(), "a log still being written lacks its summary by nature: " + s.statusText());
        assertTrue(s.log().messageCount() > firstCount, "more messages: " + s.statusText());
        assertFalse(s.log().complete());

        Files.write(growing, all); // the spy closed it: summary and footer
        threads.runUntil(s::timelineComplete, WAIT, "the second timeline pass");
        s.follow();
        threads.runUntil(() -> !s.reading(), WAIT, "the finished log");
        assertTrue(s.log().complete());
        assertEquals(-1, s.follow(), "following ends with the complete log");
        assertFalse(s.following());
        assertTrue(s.log().problems().isEmpty(), s.statusText());
        assertFalse(s.statusText().contains("still being written"), s.statusText());
    }

    @Test
    void aLookAtAGrowingLogWaitsForThePace() throws Exception {
        Path whole = spyLog("paced-whole.mcap");
        byte[] all = Files.readAllBytes(whole);
        Path growing = tmp.resolve("paced.mcap");
        Files.write(growing, Arrays.copyOf(all, all.length / 2));
        ReplaySession s = opened(growing, new FollowPace(60_000, 4));
        threads.runUntil(s::timelineComplete, WAIT, "the timeline pass");
        Files.write(growing, all);
        long next = s.follow();
        assertFalse(s.reading(), "the last look was less than a minute ago");
        assertTrue(next > 30_000 && next <= 60_000, "looks again in what is left of the minute: " + next);
    }

    @Test
    void theTransportMovesTheReplayAndPublishes() throws Exception {
        ReplaySession s = opened(spyLog("transport.mcap"), everyLook());
        SessionLog log = s.log();
        LinkedBlockingQueue<StreamMessage> received = new LinkedBlockingQueue<>();
        try (Subscription sub = bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 14), received::add)) {
            s.transport().seekSeconds(10);
            assertEquals(log.startNanos() + 10_000_000_000L, s.position());
            assertNull(s.transport().lastPublished(), "a seek publishes no message of its own");
            int moves = view.moves.get();
            s.transport().stepForward();
            assertTrue(view.moves.get() > moves, "the view is told");
            LogMessage one = s.transport().lastPublished();
            assertNotNull(one);
            s.transport().stepForward();
            LogMessage two = s.transport().lastPublished();
            s.transport().stepBack();
            assertTrue(one.samePlace(s.transport().lastPublished()), "a step back shows the entry before");
            assertNotNull(two);

            // a message chosen (an inspector row) is published
            LogMessage chosen;
            try (LogCursor c = log.cursor(log.startNanos() + 20_000_000_000L)) {
                chosen = c.next();
                while (chosen.toStreamMessage().isEmpty()) {
                    chosen = c.next();
                }
            }
            received.clear();
            s.transport().select(chosen);
            assertTrue(chosen.samePlace(s.transport().lastPublished()));
            StreamMessage want = chosen.toStreamMessage().orElseThrow();
            threads.runUntil(() -> received.stream().anyMatch(m -> m.key().equals(want.key()) && m.timeNanos() == want.timeNanos()),
                    5_000, "the chosen message on the bus");

            s.transport().toStart();
            assertEquals(log.startNanos(), s.position());
        }
        s.transport().faster();
        assertEquals(2, s.replayer().speed(), 1e-9);
        s.transport().slower();
        s.transport().slower();
        assertEquals(0.5, s.replayer().speed(), 1e-9);
        s.transport().playPause();
        assertTrue(s.replayer().playing());
        s.transport().playPause();
        assertFalse(s.replayer().playing());
    }

    @Test
    void whatStoppedPlayIsInTheStatusUntilPlayStartsAgain() throws Exception {
        Path file = spyLog("failing.mcap");
        ReplaySession s = opened(file, everyLook());
        threads.runUntil(s::timelineComplete, WAIT, "the timeline pass");
        s.transport().seek(s.log().startNanos() + (s.log().endNanos() - s.log().startNanos()) / 2);
        s.transport().stepForward(); // the cursor holds the chunk it is in; the ones after it are read as play goes on
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.WRITE)) {
            ch.truncate(ch.size() / 4); // the file is cut under the open log
        }
        assertFalse(s.alarming());
        s.transport().setSpeed(16);
        s.transport().playPause();
        threads.runUntil(() -> s.statusText().contains("Replay stopped: "), WAIT, "the failure in the status: " + s.statusText());
        Exception failure = s.replayer().failure();
        assertNotNull(failure);
        assertTrue(s.statusText().contains("Replay stopped: " + Failures.describe(failure)), s.statusText());
        assertTrue(s.alarming());
    }

    @Test
    void closingLetsTheLogGoAndEndsFollowing() throws Exception {
        ReplaySession s = opened(spyLog("closed.mcap"), everyLook());
        SharedLog shared = s.sharedLog();
        Replayer r = s.replayer();
        s.close();
        assertEquals(-1, s.follow());
        assertNull(s.log());
        threads.runUntil(shared::isClosed, WAIT, "the log to be closed");
        assertFalse(r.playing());
    }

    @Test
    void aReadingThatEndsWhenTheOwnerIsGoneIsClosed() throws Exception {
        ReplaySession s = session(spyLog("orphan.mcap"), everyLook());
        threads.ownerGone();
        int before = threads.started.get();
        s.open();
        // the reading finds no owner to hand its log to: it retires it in the background
        threads.runUntil(() -> threads.started.get() >= before + 2, WAIT, "the orphaned reading to be closed");
        assertTrue(view.shown.isEmpty());
    }

    @Test
    void speedsStepThroughTheOfferedOnes() {
        assertEquals(2, Speeds.faster(1));
        assertEquals(16, Speeds.faster(16), "the fastest stays");
        assertEquals(0.25, Speeds.slower(0.5));
        assertEquals(0.1, Speeds.slower(0.1), "the slowest stays");
        assertEquals(0.5, Speeds.faster(0.3), "between two: the next offered");
        assertEquals("0.25x", Speeds.text(0.25));
        assertEquals("16x", Speeds.text(16));
        assertEquals(Replayer.MIN_SPEED, Speeds.offered()[0]);
        assertEquals(Replayer.MAX_SPEED, Speeds.offered()[Speeds.offered().length - 1]);
    }

    /** The first entry after {@code last} (read straight from {@code log}) that publishes something. */
    private static LogMessage publishedAfter(SessionLog log, LogMessage last) throws IOException {
        try (LogCursor c = log.cursor(last.timeNanos())) {
            LogMessage m = c.next();
            while (m != null && !m.samePlace(last)) {
                m = c.next();
            }
            assertNotNull(m, "the last published message is in the reopened log");
            for (m = c.next(); m != null; m = c.next()) {
                if (m.toStreamMessage().isPresent()) {
                    return m;
                }
            }
        }
        throw new AssertionError("nothing published after " + last);
    }
}
