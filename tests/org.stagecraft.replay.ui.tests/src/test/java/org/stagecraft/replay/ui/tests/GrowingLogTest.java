package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.StandardOpenOption;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * The demo opens its live spy log while the spy still writes it: the log has no summary yet. The editor
 * opens what is in the file, and Reload shows what was added since, keeping the replay position.
 */
@Timeout(180)
class GrowingLogTest {
    private final IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();

    @AfterEach
    void close() {
        page.closeAllEditors(false);
    }

    @Test
    void aLogStillBeingWrittenOpensAndReloadShowsTheRest() throws Exception {
        IFile file = TestLogs.project().getFile("growing.mcap");
        var path = file.getLocation().toPath();
        Files.deleteIfExists(path);
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                SpyLogWriter w = SpyLogWriter.create(ch, Map.of(), 64 << 10);
                TestLogs.Feeder feeder = new TestLogs.Feeder(TraceCorpus.file(TestLogs.TRACE), w)) {
            feeder.writeUntil(10);
            w.flush(); // what a running spy has on disk: chunks, no summary, no footer
            file.refreshLocal(0, null);

            SessionLogEditor e = SessionLogEditorTest.open(page, file);
            assertNotNull(e.log(), e.statusText());
            assertTrue(e.log().endNanos() - e.log().startNanos() < 10_000_000_000L, "about the first ten seconds");
            long firstCount = e.log().messageCount();
            assertTrue(firstCount > 500, "messages so far: " + firstCount);
            SessionLogEditorTest.waitForTimeline(e);
            e.replayer().seek(e.log().startNanos() + 5_000_000_000L);
            long position = e.replayer().position();
            String source = e.sourceId();
            var bus = e.bus();

            feeder.writeUntil(20);
            w.flush();
            var before = e.log();
            Ui.press(e.transport().control(), "Reload");
            assertTrue(e.reading(), "read again in the background");
            Ui.spinUntil(() -> !e.reading() && e.log() != before, 60_000, "the log read again");
            assertTrue(e.log().endNanos() - e.log().startNanos() > 15_000_000_000L, "the log grew: " + e.statusText());
            assertTrue(e.log().messageCount() > firstCount);
            assertEquals(position, e.replayer().position(), "the replay stays where it was");
            assertEquals(source, e.sourceId(), "views following the log keep following it");
            assertTrue(bus == e.bus() && !bus.isClosed());
            SessionLogEditorTest.waitForTimeline(e);
            SessionLogEditorTest.waitForInspector(e);
        }
    }

    @Test
    void theEditorFollowsALogAsTheSpyWritesItUntilTheSpyClosesIt() throws Exception {
        IFile file = TestLogs.project().getFile("followed.mcap");
        var path = file.getLocation().toPath();
        Files.deleteIfExists(path);
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                SpyLogWriter w = SpyLogWriter.create(ch, Map.of(), 64 << 10);
                TestLogs.Feeder feeder = new TestLogs.Feeder(TraceCorpus.file(TestLogs.TRACE), w)) {
            feeder.writeUntil(5);
            w.flush();
            file.refreshLocal(0, null);
            SessionLogEditor e = SessionLogEditorTest.open(page, file);
            long firstCount = e.log().messageCount();
            assertFalse(e.log().complete());

            feeder.writeUntil(15);
            w.flush(); // no Reload pressed: the editor sees the file grow
            Ui.spinUntil(() -> e.log() != null && e.log().messageCount() > firstCount, 30_000,
                    "the editor read the grown log by itself");
            assertTrue(e.following());
            assertTrue(e.statusText().contains("still being written"), e.statusText());

            feeder.writeUntil(20);
            feeder.close();
            w.close(); // the spy stops: summary and footer written
            Ui.spinUntil(() -> e.log() != null && e.log().complete(), 30_000, "the editor read the finished log");
            assertFalse(e.following(), "following ends with the complete log");
            assertTrue(e.log().problems().isEmpty(), e.statusText());
        }
    }
}
