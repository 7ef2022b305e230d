package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;

/**
 * The analysis models on a log opened by {@link SessionLogs} (the trace goes through a spy log and
 * its two-way cursor), checked against a plain forward read of the same log.
 */
class AnalysisOnOpenedLogsTest {
    private final MessageColumns columns = new MessageColumns(ListLog.REGISTRY);

    @Test
    void windowsDensityAndSeriesAgreeWithAForwardRead() throws Exception {
        try (SessionLog log = SessionLogs.open(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl"))) {
            List<LogMessage> all = new ArrayList<>();
            try (LogCursor c = log.cursor(log.startNanos())) {
                for (LogMessage m = c.next(); m != null; m = c.next()) {
                    all.add(m);
                }
            }
            assertTrue(all.size() > 3000, "entries: " + all.size());

            MessageFilter sonar = MessageFilter.of("ranger:0", "", columns);
            List<LogMessage> scans = all.stream().filter(sonar::matches).toList();
            LogMessage anchor = scans.get(scans.size() / 3);
            MessageWindow w = MessageWindow.around(log, sonar, anchor, 50, 50, 100_000);
            int at = indexOf(scans, anchor);
            assertEquals(100, w.rows().size());
            for (int i = 0; i < 100; i++) {
                assertTrue(w.rows().get(i).message().samePlace(scans.get(at - 50 + i)), "row " + i);
            }
            assertTrue(w.rows().stream().noneMatch(InspectorRow::marked), "a clean recording has no marks");

            TimelineDensity.Snapshot d = TimelineDensity.scan(log, 200, columns, f -> { }, () -> false).snapshot();
            assertEquals(all.size(), d.messages());
            long laser = all.stream().filter(MessageFilter.of("laser:0", "", columns)::matches).count();
            assertEquals(laser, d.tracks().stream().filter(t -> t.label().startsWith("laser:0 DATA SCAN")).mapToLong(TimelineDensity.Track::total).sum());

            Series px = SeriesSampler.sample(log, List.of(SeriesText.spec("position2d.pos.px", ListLog.REGISTRY)),
                    log.startNanos(), log.endNanos(), 100, () -> false).get(0);
            long positions = all.stream().filter(MessageFilter.of("position2d", "", columns)::matches).count();
            assertEquals(positions, px.matched());
            assertTrue(px.size() <= 200);
        }
    }

    private static int indexOf(List<LogMessage> list, LogMessage m) {
        for (int i = 0; i < list.size(); i++) {
            if (list.get(i).samePlace(m)) {
                return i;
            }
        }
        throw new AssertionError("not found");
    }
}
