package org.stagecraft.replay.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.stagecraft.replay.export.ExportFilter;
import org.stagecraft.replay.log.LogFormat;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.ui.SessionLogEditor;
import org.stagecraft.replay.ui.internal.ExportMenu;
import org.stagecraft.replay.ui.internal.LogExport;

/**
 * The editor's export actions, past their file dialogs: a CSV of a time range with the inspector's
 * filter, the whole log as writelog and as MCAP, each written by a background job while the editor
 * stays open.
 */
@Timeout(180)
class ExportActionsTest {
    private final IWorkbenchPage page = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();

    @AfterEach
    void close() {
        page.closeAllEditors(false);
    }

    private static IStatus finish(Job job) {
        Ui.spinUntil(() -> job.getResult() != null, 60_000, "the export job");
        return job.getResult();
    }

    @Test
    void csvOfATimeRangeWithTheInspectorFilterAndTheWholeLogAsWritelogAndMcap() throws Exception {
        SessionLogEditor e = SessionLogEditorTest.open(page, TestLogs.trace());
        e.inspector().setFilter("position2d:0", "");
        ExportFilter filter = ExportMenu.filterOf(e, 5.0, 10.0);
        Path dir = Files.createTempDirectory("replay-ui-export");
        try {
            Path csv = dir.resolve("pose.csv");
            IStatus s = finish(LogExport.start(e.file(), LogExport.Kind.CSV, filter, e.columns().registry(), csv));
            assertTrue(s.isOK(), s.getMessage());
            List<String> lines = Files.readAllLines(csv, StandardCharsets.UTF_8);
            assertTrue(lines.get(0).startsWith("time,conn,dir,iface,index,type,subtype"), lines.get(0));
            assertTrue(lines.get(0).contains("pos.px"), lines.get(0));
            assertTrue(lines.size() > 20, "about 5 s of position data: " + lines.size());
            assertTrue(lines.stream().skip(1).allMatch(l -> l.contains(",position2d,")), "only the filtered device");
            assertTrue(s.getMessage().contains((lines.size() - 1) + " rows"), s.getMessage());

            Path writelog = dir.resolve("whole.log");
            s = finish(LogExport.start(e.file(), LogExport.Kind.WRITELOG, ExportFilter.all(), e.columns().registry(), writelog));
            assertTrue(s.isOK(), s.getMessage());
            assertTrue(Files.readString(writelog).startsWith("## Player version"), "a writelog header");
            // a writelog file (named as Player names them) opens in the Session Log editor by its header
            var file = TestLogs.project().getFile("writelog_2026_11_24_10_00_00.log");
            if (file.exists()) {
                file.delete(true, null);
            }
            Files.copy(writelog, file.getLocation().toPath());
            file.refreshLocal(0, null);
            var part = org.eclipse.ui.ide.IDE.openEditor(page, file);
            assertTrue(part instanceof SessionLogEditor, "the default editor of a writelog file: " + part);
            SessionLogEditor w = SessionLogEditorTest.waitForOpen((SessionLogEditor) part);
            assertEquals(LogFormat.WRITELOG, w.log().format(), w.statusText());
            SessionLogEditorTest.waitForTimeline(w);
            assertTrue(w.timeline().trackLabels().stream().anyMatch(t -> t.startsWith("laser:0 DATA")), w.timeline().trackLabels().toString());
            page.closeEditor(w, false);

            Path mcap = dir.resolve("whole.mcap");
            s = finish(LogExport.start(e.file(), LogExport.Kind.MCAP, ExportFilter.all(), e.columns().registry(), mcap));
            assertTrue(s.isOK(), s.getMessage());
            // the recording's one robot, as Foxglove's own messages (checked in detail by the replay bundle's tests)
            assertTrue(s.getMessage().contains("1 robot on "), s.getMessage());
            assertTrue(new String(Files.readAllBytes(mcap), StandardCharsets.ISO_8859_1).contains("foxglove.LaserScan"),
                    "a foxglove.LaserScan channel");
            try (SessionLog back = SessionLogs.open(mcap)) {
                assertEquals(LogFormat.SPY_LOG, back.format(), "the export is also a spy log");
                assertEquals(e.log().messageCount(), back.messageCount(), "every wire entry");
            }
            assertTrue(e.replayer() != null && e.log() != null, "the editor stays usable");
        } finally {
            try (var files = Files.list(dir)) {
                for (Path p : files.toList()) {
                    Files.delete(p);
                }
            }
            Files.delete(dir);
        }
    }
}
