package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.swt.SWT;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.replay.export.ExportFilter;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.play.Replayer;
import org.stagecraft.replay.ui.PlotView;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.replay.session.FollowPace;
import org.stagecraft.replay.ui.internal.LogExport;
import org.stagecraft.replay.session.SharedLog;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;

/**
 * Reading a log again (Reload, or following a growing file) happens in the background while the editor
 * stays usable; the replay goes on just after the message last published without publishing it again;
 * readers of the replaced log (export, inspector, plot, timeline) finish on it before it is closed; a
 * failure that stops play is shown in the status line.
 */
@Timeout(180)
@LogsErrors({ "CSV export of .*notes\\.mcap.* failed" })
class ReloadTest {
    private final IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();

    @AfterEach
    void close() {
        page.closeAllEditors(false);
    }

    private static IStatus finish(Job job) {
        Ui.spinUntil(() -> job.getResult() != null, 60_000, "the export job");
        return job.getResult();
    }

    private static void reloadAndWait(SessionLogEditor e) {
        SessionLog before = e.log();
        e.reload();
        Ui.spinUntil(() -> !e.reading() && e.log() != before, 60_000, "the log read again");
    }

    /** The first entry after {@code last} (read straight from {@code log}) that publishes something. */
    private static LogMessage publishedAfter(SessionLog log, LogMessage last) throws Exception {
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

    @Test
    void reloadReadsInTheBackgroundAndGoesOnJustAfterTheLastPublishedMessage() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.spyLog("reloaded.mcap", 32 << 10));
        SessionLogEditorTest.waitForTimeline(e);
        Replayer r = e.replayer();
        r.seek(e.log().startNanos() + 5_000_000_000L);
        LogMessage last = null;
        for (int i = 0; i < 100 && (last == null || last.toStreamMessage().isEmpty()); i++) {
            last = r.stepForward();
        }
        assertTrue(last != null && last.toStreamMessage().isPresent(), "a step published a message");
        StreamKey lastKey = last.toStreamMessage().get().key();
        SessionLog oldLog = e.log();
        SharedLog oldShared = e.sharedLog();

        LinkedBlockingQueue<StreamMessage> received = new LinkedBlockingQueue<>();
        try (Subscription s = e.bus().subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 16), received::add)) {
            e.reload();
            // no display events ran since: the new reading cannot be in place yet, the old one is still usable
            assertTrue(e.reading(), "read in the background");
            assertTrue(e.statusText().contains("reading\u2026"), e.statusText());
            assertSame(oldLog, e.log());
            assertSame(r, e.replayer());
            assertFalse(oldShared.isClosed());
            assertEquals(last.timeNanos(), e.replayer().position());

            Ui.spinUntil(() -> !e.reading() && e.log() != oldLog, 60_000, "the log read again");
            Ui.spinUntil(oldShared::isClosed, 30_000, "the replaced log to be closed once its readers are done");
            assertFalse(e.statusText().contains("reading\u2026"), e.statusText());
            assertTrue(e.replayer() != r);
            LogMessage shown = e.replayer().lastPublished();
            assertTrue(shown != null && shown.samePlace(last), "the new replayer counts the message as published: " + shown);

            LogMessage expected = publishedAfter(e.log(), last);
            LogMessage stepped = null;
            for (int i = 0; i < 100 && (stepped == null || stepped.toStreamMessage().isEmpty()); i++) {
                stepped = e.replayer().stepForward();
            }
            assertTrue(stepped != null && stepped.samePlace(expected), "the next step publishes the message after it: " + stepped);
            StreamKey expectedKey = expected.toStreamMessage().get().key();
            Ui.spinUntil(() -> received.stream().anyMatch(m -> m.key().equals(expectedKey) && m.timeNanos() == expected.timeNanos()),
                    5_000, "the step's message on the bus");
            // derived streams and device replies aside, the first message on the bus since the reload is the step's, not the old one again
            // (device replies a seek publishes are from before the position)
            long at = last.timeNanos();
            StreamMessage first = received.stream()
                    .filter(m -> (m.key().equals(expectedKey) || m.key().equals(lastKey)) && m.timeNanos() >= at).findFirst()
                    .orElseThrow();
            assertEquals(expectedKey, first.key());
            assertEquals(expected.timeNanos(), first.timeNanos());
        }
    }

    @Test
    void anExportAndThePlotGoOnWhileTheLogIsReadAgain() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.spyLog("exported.mcap", 32 << 10));
        PlotView plot = e.showPlot();
        for (String s : List.copyOf(plot.seriesTexts())) {
            plot.removeSeries(s);
        }
        plot.addSeries("position2d.pos.px");
        Path dir = Files.createTempDirectory("replay-ui-reload-export");
        try {
            Path quiet = dir.resolve("quiet.csv");
            IStatus s = finish(LogExport.start(e.file(), LogExport.Kind.CSV, ExportFilter.all(), e.columns().registry(), quiet));
            assertTrue(s.isOK(), s.getMessage());

            Path busy = dir.resolve("busy.csv");
            Job export = LogExport.start(e.file(), LogExport.Kind.CSV, ExportFilter.all(), e.columns().registry(), busy);
            List<SharedLog> replaced = new ArrayList<>();
            for (int i = 0; i < 3; i++) {
                replaced.add(e.sharedLog());
                plot.addSeries("laser mean(ranges)"); // a sampling pass on the log about to be replaced
                reloadAndWait(e);
            }
            s = finish(export);
            assertTrue(s.isOK(), s.getMessage());
            assertEquals(Files.readAllLines(quiet, StandardCharsets.UTF_8), Files.readAllLines(busy, StandardCharsets.UTF_8),
                    "the export written during reloads is whole");
            Ui.spinUntil(() -> replaced.stream().allMatch(SharedLog::isClosed), 30_000, "every replaced log closed");
            Ui.spinUntil(() -> !plot.sampling() && plot.series().size() == 4 && plot.series().stream().allMatch(x -> x.size() > 0),
                    30_000, "the plot sampled the log on show");
            assertNotNull(plot.canvas());
            SessionLogEditorTest.waitForInspector(e);
            assertFalse(e.inspector().statusText().startsWith("cannot read"), e.inspector().statusText());
            SessionLogEditorTest.waitForTimeline(e);
        } finally {
            try (var files = Files.list(dir)) {
                for (Path p : files.toList()) {
                    Files.delete(p);
                }
            }
            Files.delete(dir);
            page.hideView(plot);
        }
    }

    @Test
    void aFailedExportSaysWhyAndLeavesNoFile() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.trace());
        Path dir = Files.createTempDirectory("replay-ui-failed-export");
        Path notALog = dir.resolve("notes.mcap");
        Files.writeString(notALog, "not a log\n");
        Path out = dir.resolve("out.csv");
        try {
            IStatus s = finish(LogExport.start(notALog, LogExport.Kind.CSV, ExportFilter.all(), e.columns().registry(), out));
            assertEquals(IStatus.ERROR, s.getSeverity());
            assertTrue(s.getMessage().contains("failed: IOException: " + notALog), s.getMessage());
            assertFalse(Files.exists(out));
        } finally {
            Files.deleteIfExists(notALog);
            Files.deleteIfExists(out);
            Files.delete(dir);
        }
    }

    @Test
    void aFailureThatStopsPlayIsShownInRed() throws Exception {
        var file = TestLogs.spyLog("failing.mcap", 16 << 10);
        SessionLogEditor e = SessionLogEditorTest.open(page, file);
        SessionLogEditorTest.waitForTimeline(e);
        SessionLogEditorTest.waitForInspector(e);
        Replayer r = e.replayer();
        r.seek(e.log().startNanos() + (e.log().endNanos() - e.log().startNanos()) / 2);
        r.stepForward(); // the cursor holds the chunk it is in; the ones after it are read as play goes on
        try (FileChannel ch = FileChannel.open(file.getLocation().toPath(), StandardOpenOption.WRITE)) {
            ch.truncate(ch.size() / 4); // the file is cut under the open log
        }
        assertFalse(e.statusText().contains("Replay stopped"), e.statusText());
        r.setSpeed(Replayer.MAX_SPEED);
        r.play();
        Ui.spinUntil(() -> e.statusText().contains("Replay stopped: "), 60_000, "the failure in the status line: " + e.statusText());
        assertNotNull(r.failure());
        assertFalse(r.playing());
        assertTrue(e.statusText().contains(r.failure().getClass().getSimpleName()), e.statusText());
        var label = statusLabel(e);
        Ui.spinUntil(() -> label.getText().contains("Replay stopped"), 5_000, "the label to show it");
        assertEquals(label.getDisplay().getSystemColor(SWT.COLOR_DARK_RED), label.getForeground());
    }

    /** The status line: the wrapping label under the transport bar. */
    private static org.eclipse.swt.widgets.Label statusLabel(SessionLogEditor e) {
        for (var c : e.transport().control().getParent().getChildren()) {
            if (c instanceof org.eclipse.swt.widgets.Label l && (l.getStyle() & SWT.WRAP) != 0) {
                return l;
            }
        }
        throw new AssertionError("no status line");
    }

    @Test
    void followingWaitsAMultipleOfWhatTheLastLookCost() {
        FollowPace pace = new FollowPace(2000, 4);
        assertEquals(2000, pace.delayMillis(), "a cheap log is looked at every two seconds");
        pace.reopened(1_500_000_000L);
        pace.timelinePassed(1_000_000_000L);
        assertEquals(10_000, pace.delayMillis(), "four times a 2.5 s look");
        pace.reopened(100_000_000L);
        pace.timelinePassed(100_000_000L);
        assertEquals(2000, pace.delayMillis());
    }
}
