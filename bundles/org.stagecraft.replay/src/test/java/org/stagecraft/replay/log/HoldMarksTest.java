package org.stagecraft.replay.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.HoldEntry.Action;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.ConnectionInfo;

/** The Session Log editor's view of a log's robot holds: spans, ticks, held-back program messages. */
class HoldMarksTest {
    @TempDir
    Path tmp;

    private static HoldEntry e(long t, int conn, Action a, long programOffset, String text) {
        return new HoldEntry(t, conn, conn == 0 ? 0 : 6665, a, programOffset, programOffset, new byte[conn == 0 ? 0 : 48], text);
    }

    private static LogMessage program(int conn, Direction dir, long offset) {
        return new LogMessage(10, new ConnectionInfo(conn, 6665, "c", "l", "u"), dir, offset, LogMessage.Kind.FRAME,
                new byte[48], null, "");
    }

    @Test
    void spansTicksAndHeldBackMessages() {
        HoldMarks m = new HoldMarks(List.of(e(100, 0, Action.HOLD_ON, 0, "suspended in the debugger"),
                e(101, 1, Action.INJECTED, 960, "zero velocity"), e(150, 1, Action.HELD_BACK, 1008, "held"),
                e(200, 0, Action.HOLD_OFF, 0, ""), e(300, 0, Action.HOLD_ON, 0, "emergency stop")), 400);
        assertEquals(List.of(new HoldMarks.Span(100, 200, "suspended in the debugger"),
                new HoldMarks.Span(300, 400, "emergency stop")), m.spans(), "a hold on at the end runs to the log's end");
        assertEquals(List.of(101L), m.injectedTimes());
        assertEquals(List.of(150L), m.heldBackTimes());
        assertTrue(m.heldBack(program(1, Direction.CLIENT_TO_SERVER, 1008)));
        assertFalse(m.heldBack(program(1, Direction.CLIENT_TO_SERVER, 960)), "the message before it went to Player");
        assertFalse(m.heldBack(program(2, Direction.CLIENT_TO_SERVER, 1008)), "another connection");
        assertFalse(m.heldBack(program(1, Direction.SERVER_TO_CLIENT, 1008)), "Player's stream is never held");
        assertTrue(HoldMarks.none().isEmpty());
    }

    @Test
    void robotDataBreakpointHitsMarkTheirMessageFromPlayer() throws Exception {
        HoldMarks m = new HoldMarks(List.of(e(100, 1, Action.BREAK, 5000, "robot data breakpoint: laser:0 min(ranges) < 0.3"),
                e(101, 0, Action.HOLD_ON, 0, "robot data breakpoint"), e(120, 1, Action.PASSED_ON, 5000, "after 20 ms")), 400);
        assertEquals(List.of(100L), m.breakTimes());
        assertTrue(m.triggeredBreak(program(1, Direction.SERVER_TO_CLIENT, 5000)));
        assertFalse(m.triggeredBreak(program(1, Direction.CLIENT_TO_SERVER, 5000)), "the program's own stream");
        assertFalse(m.triggeredBreak(program(1, Direction.SERVER_TO_CLIENT, 5048)), "the message after it");
        assertFalse(m.isEmpty());
        // written and read back: the log's hold channel keeps the new actions
        Path file = tmp.resolve("break.mcap");
        try (SpyLogWriter w = SpyLogWriter.create(file, Map.of())) {
            w.connectionOpened(1_000, 1, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");
            w.hold(e(2_000, 1, Action.BREAK, 5000, "robot data breakpoint"));
            w.hold(e(3_000, 1, Action.PASSED_ON, 5000, "passed on"));
            w.connectionClosed(4_000, 1, "done");
        }
        try (SessionLog log = SessionLogs.open(file)) {
            assertEquals(List.of(Action.BREAK, Action.PASSED_ON), log.holdEntries().stream().map(HoldEntry::action).toList());
        }
    }

    @Test
    void frozenWorldsAreSpansOfTheirOwnWrittenAndReadBack() throws Exception {
        Path file = tmp.resolve("frozen.mcap");
        try (SpyLogWriter w = SpyLogWriter.create(file, Map.of())) {
            w.connectionOpened(1_000, 1, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");
            w.hold(e(2_000, 0, Action.HOLD_ON, 0, "suspended in the debugger"));
            w.hold(e(2_100, 0, Action.WORLD_FROZEN, 0, "world frozen at simulated time 12.300 s"));
            w.hold(e(5_000, 0, Action.WORLD_THAWED, 0, "world runs on"));
            w.hold(e(5_050, 0, Action.HOLD_OFF, 0, ""));
            w.hold(e(6_000, 0, Action.WORLD_FROZEN, 0, "world frozen at simulated time 15.000 s"));
            w.connectionClosed(7_000, 1, "done");
        }
        try (SessionLog log = SessionLogs.open(file)) {
            HoldMarks m = new HoldMarks(log.holdEntries(), 9_000);
            assertEquals(List.of(new HoldMarks.Span(2_100, 5_000, "world frozen at simulated time 12.300 s"),
                    new HoldMarks.Span(6_000, 9_000, "world frozen at simulated time 15.000 s")), m.frozenSpans(),
                    "a world still frozen at the end is drawn to the log's end");
            assertEquals(List.of(new HoldMarks.Span(2_000, 5_050, "suspended in the debugger")), m.spans(), "holds are their own spans");
        }
    }

    @Test
    void aSpyLogsHoldEntriesReachTheSessionLog() throws Exception {
        Path file = tmp.resolve("held.mcap");
        try (SpyLogWriter w = SpyLogWriter.create(file, Map.of())) {
            w.connectionOpened(1_000, 1, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");
            w.hold(e(2_000, 0, Action.HOLD_ON, 0, "suspended in the debugger"));
            w.hold(e(3_000, 0, Action.HOLD_OFF, 0, ""));
            w.connectionClosed(4_000, 1, "done");
        }
        try (SessionLog log = SessionLogs.open(file)) {
            List<HoldEntry> entries = log.holdEntries();
            assertEquals(List.of(Action.HOLD_ON, Action.HOLD_OFF), entries.stream().map(HoldEntry::action).toList());
            assertEquals(List.of(new HoldMarks.Span(2_000, 3_000, "suspended in the debugger")),
                    new HoldMarks(entries, log.endNanos()).spans());
        }
    }
}
