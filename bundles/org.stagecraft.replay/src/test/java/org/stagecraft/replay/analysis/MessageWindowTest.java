package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.log.LogMessage;

class MessageWindowTest {
    private final MessageColumns columns = new MessageColumns(ListLog.REGISTRY);
    private final ListLog log = AnalysisTestTraces.pioneer();

    private List<LogMessage> matching(MessageFilter f) {
        return log.messages().stream().filter(f::matches).toList();
    }

    @Test
    void aWindowAroundTheMiddleHoldsTheFilteredNeighboursInOrder() throws Exception {
        MessageFilter laser = MessageFilter.of("laser:0", "", columns);
        List<LogMessage> all = matching(laser);
        assertTrue(all.size() > 200, "laser scans in the recording: " + all.size());
        int middle = all.size() / 2;
        while (all.get(middle - 1).timeNanos() == all.get(middle).timeNanos()) {
            middle++; // a time anchor stands before the first entry of its time
        }
        LogMessage anchor = all.get(middle);
        MessageWindow w = MessageWindow.around(log, laser, anchor.timeNanos(), 20, 30, 100_000);
        assertEquals(50, w.rows().size());
        assertEquals(20, w.anchorIndex());
        assertTrue(w.rows().get(20).message().samePlace(anchor), () -> w.rows().get(20) + " vs " + anchor);
        int at = all.indexOf(anchor);
        for (int i = 0; i < 50; i++) {
            assertTrue(w.rows().get(i).message().samePlace(all.get(at - 20 + i)), "row " + i);
        }
        assertFalse(w.atStart());
        assertFalse(w.atEnd());
        assertTrue(w.covers(anchor.timeNanos()));
        assertEquals(20, w.indexOf(anchor));
        assertEquals(0, log.cursorsOpen, "cursors closed");
    }

    @Test
    void theEndsOfTheLogAreSaid() throws Exception {
        MessageFilter everything = MessageFilter.all(columns);
        MessageWindow first = MessageWindow.around(log, everything, Long.MIN_VALUE, 10, 5, 1000);
        assertTrue(first.atStart());
        assertEquals(0, first.anchorIndex());
        assertEquals(5, first.rows().size());
        assertTrue(first.rows().get(0).message().samePlace(log.messages().get(0)));

        MessageWindow last = MessageWindow.around(log, everything, Long.MAX_VALUE, 10, 5, 1000);
        assertTrue(last.atEnd());
        assertEquals(10, last.rows().size());
        assertEquals(10, last.anchorIndex(), "nothing at or after the anchor");
        assertTrue(last.rows().get(9).message().samePlace(log.messages().get(log.messages().size() - 1)));
    }

    @Test
    void aMessageAnchorPicksThatEntryAmongEqualTimes() throws Exception {
        // several messages often share a receive time (one recv() chunk); anchoring on the second of them
        LogMessage second = null;
        List<LogMessage> ms = log.messages();
        for (int i = 1; i < ms.size() && second == null; i++) {
            if (ms.get(i).timeNanos() == ms.get(i - 1).timeNanos()) {
                second = ms.get(i);
            }
        }
        assertTrue(second != null, "the recording has messages sharing a time");
        MessageWindow w = MessageWindow.around(log, MessageFilter.all(columns), second, 3, 3, 1000);
        assertTrue(w.rows().get(w.anchorIndex()).message().samePlace(second));
        assertEquals(3, w.anchorIndex());
    }

    @Test
    void aSparseFilterStopsAtTheScanLimitAndSaysItDidNotReachTheEnd() throws Exception {
        MessageFilter none = MessageFilter.of("", "no such text anywhere", columns);
        MessageWindow w = MessageWindow.around(log, none, log.startNanos() + (log.endNanos() - log.startNanos()) / 2, 10, 10, 500);
        assertTrue(w.isEmpty());
        assertFalse(w.atStart(), "stopped after 500 entries, not at the start");
        assertFalse(w.atEnd(), "stopped after 500 entries, not at the end");
    }

    @Test
    void freeTextLooksInSubtypeAndSummary() {
        List<LogMessage> geom = matching(MessageFilter.of("", "get_geom", columns));
        assertFalse(geom.isEmpty());
        assertTrue(geom.stream().allMatch(m -> columns.subtype(m).equals("GET_GEOM")), "only geometry requests and replies");
        assertTrue(geom.stream().anyMatch(m -> columns.type(m).equals("REQ")) && geom.stream().anyMatch(m -> columns.type(m).equals("RESP_ACK")));
        List<LogMessage> banner = matching(MessageFilter.of("", "v.3.1.1", columns));
        assertEquals(1, banner.size());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> MessageFilter.of("dev=laser", "", columns))
                .getMessage().contains("dev=laser"));
        assertTrue(matching(MessageFilter.of("laser:0", "", columns)).stream().noneMatch(m -> m.kind() != LogMessage.Kind.FRAME),
                "a stream pattern passes only published entries");
    }

    @Test
    void gapsAndProblemsAreMarked() throws Exception {
        var c = ListLog.connection(1, 6665);
        byte[] ten = new byte[10];
        List<LogMessage> ms = new ArrayList<>();
        ms.add(new LogMessage(1, c, Direction.SERVER_TO_CLIENT, 0, LogMessage.Kind.UNFRAMED, ten, null, "x"));
        ms.add(new LogMessage(2, c, Direction.SERVER_TO_CLIENT, 10, LogMessage.Kind.UNFRAMED, ten, null, "y"));
        ms.add(new LogMessage(3, c, Direction.CLIENT_TO_SERVER, 0, LogMessage.Kind.UNFRAMED, ten, null, "z"));
        ms.add(new LogMessage(4, c, Direction.SERVER_TO_CLIENT, 50, LogMessage.Kind.UNFRAMED, ten, null, "after a gap"));
        ms.add(new LogMessage(5, c, Direction.SERVER_TO_CLIENT, -1, LogMessage.Kind.DIAGNOSTIC, null, null, "queue overflow"));
        MessageWindow w = MessageWindow.around(new ListLog(ms), MessageFilter.all(columns), 0, 0, 10, 100);
        assertEquals(List.of(0L, 0L, 0L, 30L, 0L), w.rows().stream().map(InspectorRow::gapBytes).toList());
        assertTrue(w.rows().stream().allMatch(InspectorRow::marked), "unframed bytes and diagnostics are problems");
        assertTrue(w.atStart() && w.atEnd());
    }
}
