package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.LinkedBlockingQueue;

import org.eclipse.core.filesystem.EFS;
import org.eclipse.core.resources.IFile;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Table;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.core.streams.BusSources;
import org.stagecraft.replay.analysis.InspectorRow;
import org.stagecraft.replay.analysis.MessageWindow;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.replay.ui.internal.FieldTreeContent;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;
import org.stagecraft.streams.Subscription;

/**
 * The Session Log editor in a running workbench: a recorded trace and a spy log written by the spy's
 * writer open with a track per stream; stepping publishes on the editor's own bus; an inspector row
 * moves the replay; a cut-off log opens and says where it stopped. Runs on the UI thread; every wait
 * spins the display until a condition holds.
 */
@Timeout(180)
class SessionLogEditorTest {
    private IWorkbenchPage page;

    @BeforeEach
    void page() {
        page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
    }

    @AfterEach
    void closeEditors() {
        page.closeAllEditors(false);
    }

    static SessionLogEditor open(IWorkbenchPage page, IFile file) throws Exception {
        IEditorPart e = IDE.openEditor(page, file, SessionLogEditor.ID, true);
        assertTrue(e instanceof SessionLogEditor, "opened in the Session Log editor: " + e);
        return waitForOpen((SessionLogEditor) e);
    }

    /** The editor reads its file in the background: waits until that reading is in place (or failed). */
    static SessionLogEditor waitForOpen(SessionLogEditor e) {
        Ui.spinUntil(() -> !e.reading(), 60_000, "the editor to read " + e.file());
        return e;
    }

    static void waitForTimeline(SessionLogEditor e) {
        Ui.spinUntil(e::timelineComplete, 60_000, "the timeline's pass over the log");
        Ui.spinUntil(() -> e.timeline().snapshot() != null
                && e.timeline().snapshot().messages() > 0 && e.timelineComplete(), 10_000, "the timeline to show it");
        Ui.drain();
    }

    static void waitForInspector(SessionLogEditor e) {
        Ui.spinUntil(() -> !e.inspector().window().isEmpty(), 30_000, "the inspector's first window");
    }

    /** The first entry at or after {@code t} that the replay publishes, read straight from the log. */
    private static LogMessage firstPublishedFrom(SessionLogEditor e, long t) throws Exception {
        try (LogCursor c = e.log().cursor(t)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                if (m.toStreamMessage().isPresent()) {
                    return m;
                }
            }
        }
        throw new AssertionError("nothing published after " + t);
    }

    /**
     * Issue 24, item 10: after a seek the inspector shows the row the replay is at, also when the seek
     * came while the inspector was still reading a window (before, that seek was dropped and the
     * inspector stayed where the read was).
     */
    @Test
    void theInspectorShowsWhereTheReplayWasMovedWhileItWasReading() throws Exception {
        SessionLogEditor e = open(page, TestLogs.spyLog("seek.mcap", 64 << 10));
        waitForTimeline(e);
        waitForInspector(e);
        Ui.spinUntil(() -> e.inspector().statusText().contains("entries"), 30_000, "the inspector to settle");
        LogMessage at12 = firstPublishedFrom(e, e.log().startNanos() + 12_000_000_000L);
        LogMessage at27 = firstPublishedFrom(e, e.log().startNanos() + 27_000_000_000L);
        e.inspector().follow(at12.timeNanos(), at12); // outside the first window: a read starts
        e.inspector().follow(at27.timeNanos(), at27); // the replay moved again while it reads
        try {
            Ui.spinUntil(() -> e.inspector().detailed() != null && at27.samePlace(e.inspector().detailed()), 30_000,
                    "the inspector at the replay's last position (27 s)");
        } catch (AssertionError x) {
            throw new AssertionError(x.getMessage() + "; inspector: " + e.inspector().statusText() + ", detailed at "
                    + (e.inspector().detailed() == null ? "none" : (e.inspector().detailed().timeNanos() - e.log().startNanos()) / 1e9)
                    + " s, wanted " + (at27.timeNanos() - e.log().startNanos()) / 1e9 + " s", x);
        }
        Table table = e.inspector().table();
        int row = table.getSelectionIndex();
        assertTrue(row >= 0 && at27.samePlace(e.inspector().window().rows().get(row).message()), "its row is selected");
        // in sight: most of the row lies inside the table's client area (counting whole rows from the top
        // index is wrong when the top row is partly scrolled away, as GTK leaves it after showSelection)
        // (waited for: the table may still be laid out and scrolled by the events of this selection)
        Ui.spinUntil(() -> {
            Rectangle rowBounds = table.getItem(row).getBounds();
            Rectangle shown = rowBounds.intersection(table.getClientArea());
            return shown.height * 2 >= rowBounds.height;
        }, 5_000, "its row in sight: row " + row + " at " + table.getItem(row).getBounds() + ", client area "
                + table.getClientArea() + ", top " + table.getTopIndex());
    }

    @Test
    void aRecordedTraceOpensWithATrackPerStream() throws Exception {
        SessionLogEditor e = open(page, TestLogs.trace());
        assertEquals(LogFormat.PLAYER_TRACE, e.log().format());
        assertTrue(e.statusText().startsWith("Recorded trace, 3"), e.statusText());
        waitForTimeline(e);
        List<String> tracks = e.timeline().trackLabels();
        assertTrue(tracks.contains("laser:0 DATA SCAN (#1 s2c)"), tracks.toString());
        assertTrue(tracks.contains("position2d:0 DATA STATE (#1 s2c)"), tracks.toString());
        assertTrue(tracks.contains("ranger:0 DATA RANGES (#1 s2c)") || tracks.stream().anyMatch(t -> t.startsWith("ranger:0 DATA")), tracks.toString());
        assertTrue(tracks.size() >= 10, "streams: " + tracks);
        assertTrue(BusSources.find(e.sourceId()).isPresent(), "the editor's bus is a source views can follow");
        assertTrue(BusSources.find(e.sourceId()).get().bus() == e.bus());

        page.closeEditor(e, false);
        assertTrue(BusSources.find(e.sourceId()).isEmpty(), "gone with its editor");
        assertTrue(e.bus().isClosed());
    }

    @Test
    void aSpyLogOpensAndStepForwardPublishesTheNextMessageOnTheEditorsBus() throws Exception {
        SessionLogEditor e = open(page, TestLogs.spyLog("session.mcap", 64 << 10));
        assertEquals(LogFormat.SPY_LOG, e.log().format());
        assertTrue(e.log().problems().isEmpty(), e.log().problems().toString());
        waitForTimeline(e);
        assertTrue(e.timeline().trackLabels().contains("laser:0 DATA SCAN (#1 s2c)"), e.timeline().trackLabels().toString());

        // seek by typing a time, as a user does (the seek itself publishes the devices' geometry
        // replies from before that time, which the views need: listen from after it)
        var time = findText(e);
        time.setText("10");
        time.notifyListeners(SWT.DefaultSelection, new Event());
        long ten = e.log().startNanos() + 10_000_000_000L;
        assertEquals(ten, e.replayer().position());
        LinkedBlockingQueue<StreamMessage> received = new LinkedBlockingQueue<>();
        try (Subscription s = e.bus().subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 16), received::add)) {
            LogMessage next = firstPublishedFrom(e, ten);
            StreamMessage expected = next.toStreamMessage().orElseThrow();

            int steps = entriesUpTo(e, ten, next);
            for (int i = 0; i < steps; i++) {
                Ui.press(e.transport().control(), "|\u25B6"); // events and banners first, if any: they publish nothing
            }
            Ui.spinUntil(() -> !received.isEmpty(), 5_000, "the step to publish");
            StreamMessage got = received.poll();
            assertNotNull(got, "a step published something");
            assertEquals(expected.key(), got.key());
            assertEquals(expected.timeNanos(), got.timeNanos());
            assertEquals(next.timeNanos(), e.replayer().position());
            Ui.spinUntil(() -> e.timeline().position() == next.timeNanos(), 5_000, "the timeline cursor to follow");
            Ui.spinUntil(() -> e.transport().timeText().startsWith(String.format(java.util.Locale.ROOT, "%.3f",
                    (next.timeNanos() - e.log().startNanos()) / 1e9)), 5_000, "the time field to follow: " + e.transport().timeText());

            // and back: the entry before it is shown
            LogMessage before;
            try (LogCursor c = e.log().cursor(ten)) {
                c.seekTo(next);
                before = c.previous();
            }
            received.clear();
            Ui.press(e.transport().control(), "\u25C0|");
            assertTrue(before.samePlace(e.replayer().lastPublished()), "a step back shows the entry before");
            if (before.toStreamMessage().isPresent()) {
                Ui.spinUntil(() -> !received.isEmpty(), 5_000, "step back to publish");
                assertEquals(before.toStreamMessage().get().key(), received.poll().key());
            }

            // the same from the keyboard on the timeline: Right steps forward, Space plays and pauses
            received.clear();
            Event right = new Event();
            right.keyCode = SWT.ARROW_RIGHT;
            e.timeline().canvas().notifyListeners(SWT.KeyDown, right);
            Ui.spinUntil(() -> !received.isEmpty(), 5_000, "the Right key to step");
            assertEquals(expected.key(), received.poll().key());
            Event space = new Event();
            space.keyCode = ' ';
            e.timeline().canvas().notifyListeners(SWT.KeyDown, space);
            assertTrue(e.replayer().playing());
            e.timeline().canvas().notifyListeners(SWT.KeyDown, space);
            assertFalse(e.replayer().playing());
        }
    }

    /** How many steps from {@code t} reach {@code m} (one per entry, published or not). */
    private static int entriesUpTo(SessionLogEditor e, long t, LogMessage m) throws Exception {
        int n = 0;
        try (LogCursor c = e.log().cursor(t)) {
            for (LogMessage x = c.next(); x != null; x = c.next()) {
                n++;
                if (x.samePlace(m)) {
                    return n;
                }
            }
        }
        throw new AssertionError("not found");
    }

    private static org.eclipse.swt.widgets.Text findText(SessionLogEditor e) {
        for (var c : e.transport().control().getChildren()) {
            if (c instanceof org.eclipse.swt.widgets.Text t) {
                return t;
            }
        }
        throw new AssertionError("no time field");
    }

    /**
     * Issue 24, item 10: what the robot hold did is in the inspector as rows of their own among the messages
     * (before, only bands and ticks on the timeline): the zero command it injected, decoded, in the hold's
     * colour; choosing it shows its fields and leaves the replay where it is (it is no recorded message).
     */
    @Test
    void theHoldsInjectedCommandIsARowOfItsOwn() throws Exception {
        IFile f = TestLogs.project().getFile("holds.mcap");
        java.nio.file.Path out = f.getLocation().toPath();
        java.nio.file.Files.deleteIfExists(out);
        byte[] cmd = org.stagecraft.player.codec.PlayerEncoder.encode(
                new org.stagecraft.player.wire.MessageHeader(0, 6665, 4, 0, 2, 1, 0, 0, 0),
                new org.stagecraft.player.msg.Position2d.CmdVel(new org.stagecraft.player.msg.Geometry.Pose2d(0.3, 0, 0), 1));
        byte[] zero = org.stagecraft.player.codec.PlayerEncoder.encode(
                new org.stagecraft.player.wire.MessageHeader(0, 6665, 4, 0, 2, 1, 0, 0, 0),
                new org.stagecraft.player.msg.Position2d.CmdVel(new org.stagecraft.player.msg.Geometry.Pose2d(0, 0, 0), 1));
        try (org.stagecraft.spy.log.SpyLogWriter w = org.stagecraft.spy.log.SpyLogWriter.create(out, java.util.Map.of())) {
            w.connectionOpened(1_000_000, 1, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");
            for (int i = 0; i < 10; i++) {
                w.wire(2_000_000L + i * 100_000_000L, 1, 6665, org.stagecraft.player.wire.Direction.CLIENT_TO_SERVER,
                        (long) i * cmd.length, org.stagecraft.spy.log.LogEntry.Kind.FRAME, cmd, "");
            }
            w.hold(new org.stagecraft.spy.log.HoldEntry(550_000_000L, 0, 0, org.stagecraft.spy.log.HoldEntry.Action.HOLD_ON, 0, 0,
                    new byte[0], "suspended in the debugger"));
            w.hold(new org.stagecraft.spy.log.HoldEntry(550_100_000L, 1, 6665, org.stagecraft.spy.log.HoldEntry.Action.INJECTED,
                    6L * cmd.length, 6L * cmd.length, zero, "zero velocity to position2d:0 (suspended in the debugger)"));
            w.connectionClosed(2_000_000_000L, 1, "done");
        }
        f.refreshLocal(org.eclipse.core.resources.IResource.DEPTH_ZERO, null);
        SessionLogEditor e = open(page, f);
        waitForInspector(e);
        Ui.spinUntil(() -> e.inspector().window().rows().stream().anyMatch(r -> r.message().kind() == LogMessage.Kind.HOLD),
                30_000, "the hold's rows in the inspector");
        List<InspectorRow> rows = e.inspector().window().rows();
        int injected = -1;
        for (int i = 0; i < rows.size(); i++) {
            if (rows.get(i).message().kind() == LogMessage.Kind.HOLD && rows.get(i).message().text().startsWith("injected")) {
                injected = i;
            }
        }
        assertTrue(injected > 0, "an injected row: " + rows.stream().map(r -> e.columns().summary(r.message())).toList());
        assertTrue(rows.get(injected - 1).message().timeNanos() <= rows.get(injected).message().timeNanos()
                && rows.get(injected + 1).message().timeNanos() >= rows.get(injected).message().timeNanos(), "in time order");
        org.eclipse.swt.widgets.TableItem item = e.inspector().table().getItem(injected);
        assertTrue(item.getText(7).startsWith("injected by Stagecraft: zero velocity"), item.getText(7));
        assertEquals("position2d:0", item.getText(3), "decoded: its device");
        assertEquals(new org.eclipse.swt.graphics.RGB(226, 214, 248), item.getBackground().getRGB(), "in the hold's colour");
        long before = e.replayer().position();
        e.inspector().selectRow(injected);
        assertEquals(List.of("vel", "state"), FieldTreeContent.topNames(e.inspector().fields().getInput()), "its fields");
        assertEquals(before, e.replayer().position(), "the replay stays where it was");
    }

    @Test
    void selectingAnInspectorRowMovesTheReplayThereAndShowsTheMessage() throws Exception {
        SessionLogEditor e = open(page, TestLogs.spyLog("inspect.mcap", 64 << 10));
        waitForInspector(e);
        e.inspector().setFilter("position2d:0", "");
        Ui.spinUntil(() -> !e.inspector().window().isEmpty() && e.inspector().filter().patternText().equals("position2d:0")
                && e.inspector().window().rows().stream().allMatch(r -> e.columns().device(r.message()).equals("position2d:0")),
                30_000, "the filtered window");
        MessageWindow w = e.inspector().window();
        assertTrue(w.rows().size() > 20, "rows: " + w.rows().size());
        assertEquals(w.rows().size(), e.inspector().table().getItemCount(), "a virtual table of the window");

        LinkedBlockingQueue<StreamMessage> received = new LinkedBlockingQueue<>();
        try (Subscription s = e.bus().subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 16), received::add)) {
            InspectorRow row = w.rows().get(15);
            e.inspector().selectRow(15);
            assertEquals(row.message().timeNanos(), e.replayer().position(), "the replay moved to the row");
            StreamMessage want = row.message().toStreamMessage().orElseThrow();
            Ui.spinUntil(() -> received.stream().anyMatch(m -> m.key().equals(want.key()) && m.timeNanos() == want.timeNanos()),
                    5_000, "the row's message to be published");
            // besides it only what a jump publishes: the devices' geometry/configuration replies
            assertTrue(received.stream().allMatch(m -> (m.key().equals(want.key()) && m.timeNanos() == want.timeNanos())
                    || (m.key().messageType() == 4 && m.key().deviceType() != 1)), received.toString());
        }
        // its decoded fields and bytes are shown
        Object input = e.inspector().fields().getInput();
        assertEquals(List.of("pos", "vel", "stall"), FieldTreeContent.topNames(input));
        assertTrue(e.inspector().hexText().startsWith("00000000  "), e.inspector().hexText());
        assertEquals(e.inspector().detailed().bytes().length, countHexBytes(e.inspector().hexText()));
        Ui.spinUntil(() -> e.timeline().position() == e.replayer().position(), 5_000, "the timeline cursor");
        assertEquals(15, e.inspector().table().getSelectionIndex(), "the row stays selected");

        // a filter that does not parse says why and keeps the rows
        e.inspector().setFilter("dev=laser", "");
        assertTrue(e.inspector().statusText().contains("dev=laser"), e.inspector().statusText());
    }

    @Test
    void aFieldOfAMessageFromPlayerOffersARobotDataBreakpointThatReads() throws Exception {
        SessionLogEditor e = open(page, TestLogs.spyLog("break-offer.mcap", 64 << 10));
        waitForInspector(e);
        e.inspector().setFilter("position2d:0", "");
        Ui.spinUntil(() -> !e.inspector().window().isEmpty() && e.inspector().filter().patternText().equals("position2d:0")
                && e.inspector().window().rows().stream().allMatch(r -> e.columns().device(r.message()).equals("position2d:0")),
                30_000, "the filtered window");
        e.inspector().selectRow(15);
        org.eclipse.swt.widgets.Tree tree = e.inspector().fields().getTree();
        e.inspector().fields().expandAll();
        org.eclipse.swt.widgets.TreeItem pos = java.util.Arrays.stream(tree.getItems()).filter(i -> i.getText(0).equals("pos"))
                .findFirst().orElseThrow();
        org.eclipse.swt.widgets.TreeItem px = java.util.Arrays.stream(pos.getItems()).filter(i -> i.getText(0).equals("px"))
                .findFirst().orElseThrow();
        tree.setSelection(px);
        String text = e.inspector().breakpointText();
        assertTrue(text != null && text.startsWith("position2d:0 pos.px < "), text);
        org.stagecraft.replay.fields.StreamCondition.parse(text, org.stagecraft.player.codec.CodecRegistry.standard());
        tree.setSelection(pos);
        assertEquals(null, e.inspector().breakpointText(), "a struct holds no number");
    }

    private static int countHexBytes(String dump) {
        int n = 0;
        for (String line : dump.split("\n")) {
            String hex = line.substring(10, Math.min(line.length(), 59));
            n += hex.trim().isEmpty() ? 0 : hex.trim().split("\\s+").length;
        }
        return n;
    }

    @Test
    void aTruncatedLogOpensWhatIsReadableAndSaysWhereItStopped() throws Exception {
        IFile whole = TestLogs.spyLog("whole.mcap", 32 << 10);
        Path cut = TestLogs.truncated(whole, 0.6);
        try {
            IEditorPart part = IDE.openEditorOnFileStore(page, EFS.getLocalFileSystem().getStore(cut.toUri()));
            assertTrue(part instanceof SessionLogEditor, "an .mcap from outside the workspace opens in the Session Log editor: " + part);
            SessionLogEditor e = waitForOpen((SessionLogEditor) part);
            assertNotNull(e.log(), e.statusText());
            List<LogProblem> problems = e.log().problems();
            assertFalse(problems.isEmpty(), "the cut is reported");
            String status = e.statusText();
            assertTrue(status.startsWith("Spy log"), status);
            assertTrue(status.contains(problems.get(0).where()), "the status says where: " + status);
            waitForTimeline(e);
            assertFalse(e.timeline().trackLabels().isEmpty(), "the readable part has its streams");
            waitForInspector(e);
            // it replays: a step publishes
            LinkedBlockingQueue<StreamMessage> received = new LinkedBlockingQueue<>();
            try (Subscription s = e.bus().subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 10), received::add)) {
                e.replayer().seek(e.log().startNanos() + (e.log().endNanos() - e.log().startNanos()) / 2);
                for (int i = 0; i < 20 && received.isEmpty(); i++) {
                    e.replayer().stepForward();
                }
                Ui.spinUntil(() -> !received.isEmpty(), 5_000, "a replayed message from the readable part");
            }
            Optional<Long> stop = problems.stream().map(LogProblem::timeNanos).findFirst();
            assertTrue(stop.isPresent());
        } finally {
            page.closeAllEditors(false);
            Files.deleteIfExists(cut);
        }
    }

    @Test
    void aFileThatIsNoLogSaysSoInsteadOfFailing() throws Exception {
        IFile junk = TestLogs.project().getFile("junk.mcap");
        Files.writeString(junk.getLocation().toPath(), "this is not a spy log\n");
        junk.refreshLocal(0, null);
        SessionLogEditor e = open(page, junk);
        assertTrue(e.log() == null, "nothing readable");
        assertTrue(e.statusText().startsWith("Cannot open " + junk.getLocation().toPath()), e.statusText());
    }
}
