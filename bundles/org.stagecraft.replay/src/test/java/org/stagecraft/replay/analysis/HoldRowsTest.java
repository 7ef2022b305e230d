package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerEncoder;
import org.stagecraft.player.msg.ByteArray;
import org.stagecraft.player.msg.FloatArray;
import org.stagecraft.player.msg.Geometry.Pose2d;
import org.stagecraft.player.msg.Laser;
import org.stagecraft.player.msg.Position2d;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.spy.log.HoldEntry;
import org.stagecraft.spy.log.HoldEntry.Action;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * Issue 24, item 10: what the robot hold did is in the packet inspector as rows among the messages — the
 * zero command it injected, a data breakpoint's hit, the hold and the frozen world starting and ending — in
 * time order, under a device filter with that device's messages, and the program's held-back message once
 * (on its own row, not again).
 */
class HoldRowsTest {
    private static final CodecRegistry CODECS = CodecRegistry.standard();
    private static final MessageColumns COLUMNS = new MessageColumns(CODECS);

    @TempDir
    Path tmp;

    private static byte[] laser(double t) {
        return PlayerEncoder.encode(new MessageHeader(0, 6665, Laser.CODE, 0, 1, 1, t, 0, 0), new Laser.Scan(-1f, 1f, 1f, 8f, 3,
                FloatArray.of(2f, 0.25f, 3f), 0, ByteArray.EMPTY, 0));
    }

    private static byte[] vel(double vx) {
        return PlayerEncoder.encode(new MessageHeader(0, 6665, Position2d.CODE, 0, 2, 1, 0, 0, 0),
                new Position2d.CmdVel(new Pose2d(vx, 0, 0), 1));
    }

    private Path log() throws Exception {
        Path file = tmp.resolve("holds.mcap");
        byte[] scan = laser(1.0), cmd = vel(0.4), zero = vel(0);
        try (SpyLogWriter w = SpyLogWriter.create(file, Map.of())) {
            w.connectionOpened(1_000, 1, "127.0.0.1:40000", "127.0.0.1:6665", "127.0.0.1:7665");
            w.wire(2_000, 1, 6665, Direction.SERVER_TO_CLIENT, 0, LogEntry.Kind.FRAME, scan, "");
            w.hold(new HoldEntry(2_000, 1, 6665, Action.BREAK, 0, 0, scan, "robot data breakpoint: laser:0 min(ranges) < 0.3"));
            w.hold(new HoldEntry(2_001, 0, 0, Action.HOLD_ON, 0, 0, new byte[0], "robot data breakpoint"));
            w.hold(new HoldEntry(2_002, 1, 6665, Action.INJECTED, 0, 0, zero, "zero velocity to position2d:0 (robot data breakpoint)"));
            w.hold(new HoldEntry(2_003, 0, 0, Action.WORLD_FROZEN, 0, 0, new byte[0], "at simulated time 1.000 s"));
            w.wire(3_000, 1, 6665, Direction.CLIENT_TO_SERVER, 0, LogEntry.Kind.FRAME, cmd, "");
            w.hold(new HoldEntry(3_000, 1, 6665, Action.HELD_BACK, 0, 0, cmd, "held back (robot data breakpoint)"));
            w.hold(new HoldEntry(4_000, 0, 0, Action.WORLD_THAWED, 0, 0, new byte[0], "after 2.0 s"));
            w.hold(new HoldEntry(4_001, 0, 0, Action.HOLD_OFF, 0, 0, new byte[0], ""));
            w.wire(5_000, 1, 6665, Direction.SERVER_TO_CLIENT, scan.length, LogEntry.Kind.FRAME, laser(2.0), "");
            w.connectionClosed(6_000, 1, "done");
        }
        return file;
    }

    private static String describe(LogMessage m) {
        return m.kind() + " " + COLUMNS.summary(m);
    }

    @Test
    void theHoldsRowsLieAmongTheMessagesInTimeOrder() throws Exception {
        try (SessionLog log = SessionLogs.open(log(), CODECS)) {
            MessageWindow w = MessageWindow.around(log, MessageFilter.all(COLUMNS), log.startNanos(), 0, 100, 10_000);
            List<String> rows = w.rows().stream().map(r -> describe(r.message())).toList();
            List<LogMessage.Kind> kinds = w.rows().stream().map(r -> r.message().kind()).toList();
            assertEquals(List.of(LogMessage.Kind.OPENED, LogMessage.Kind.FRAME, LogMessage.Kind.HOLD, LogMessage.Kind.HOLD,
                    LogMessage.Kind.HOLD, LogMessage.Kind.HOLD, LogMessage.Kind.FRAME, LogMessage.Kind.HOLD, LogMessage.Kind.HOLD,
                    LogMessage.Kind.FRAME, LogMessage.Kind.CLOSED), kinds, String.join("\n", rows));
            assertEquals("HOLD robot data breakpoint: laser:0 min(ranges) < 0.3", rows.get(2));
            assertEquals("HOLD robots held: robot data breakpoint", rows.get(3));
            assertEquals("HOLD injected by Stagecraft: zero velocity to position2d:0 (robot data breakpoint)", rows.get(4));
            assertEquals("HOLD world frozen: at simulated time 1.000 s", rows.get(5));
            assertEquals("HOLD world runs on: after 2.0 s", rows.get(7));
            assertEquals("HOLD robots released: ", rows.get(8));
            // the injected command is decoded, towards Player, like the program's own commands
            LogMessage injected = w.rows().get(4).message();
            assertEquals(Direction.CLIENT_TO_SERVER, injected.dir());
            assertTrue(injected.decoded().body() instanceof Position2d.CmdVel v && v.vel().px() == 0, String.valueOf(injected.decoded()));
            assertEquals("position2d:0", COLUMNS.device(injected));
        }
    }

    @Test
    void aDeviceFilterKeepsWhatTheHoldDidToThatDevice() throws Exception {
        try (SessionLog log = SessionLogs.open(log(), CODECS)) {
            MessageWindow w = MessageWindow.around(log, MessageFilter.of("position2d:0 CMD", "", COLUMNS), log.startNanos(), 0, 100,
                    10_000);
            List<String> rows = w.rows().stream().map(r -> describe(r.message())).toList();
            assertEquals(2, rows.size(), String.join("\n", rows));
            assertTrue(rows.get(0).startsWith("HOLD injected by Stagecraft: zero velocity"), rows.get(0));
            assertTrue(rows.get(1).startsWith("FRAME "), "the program's command, held back, on its own row: " + rows.get(1));
            MessageWindow text = MessageWindow.around(log, MessageFilter.of("", "world frozen", COLUMNS), log.startNanos(), 0,
                    100, 10_000);
            assertEquals(1, text.rows().size(), "free text finds the hold's rows too");
        }
    }

    @Test
    void aWindowInTheMiddleTakesOnlyTheHoldsWithinItsSpan() throws Exception {
        try (SessionLog log = SessionLogs.open(log(), CODECS)) {
            // anchored at the program's command (3 000 ns): one row before it, one from it
            MessageWindow w = MessageWindow.around(log, MessageFilter.all(COLUMNS), 3_000, 1, 1, 10_000);
            List<LogMessage.Kind> kinds = w.rows().stream().map(r -> r.message().kind()).toList();
            assertEquals(List.of(LogMessage.Kind.FRAME, LogMessage.Kind.HOLD, LogMessage.Kind.HOLD, LogMessage.Kind.HOLD,
                    LogMessage.Kind.HOLD, LogMessage.Kind.FRAME), kinds,
                    w.rows().stream().map(r -> describe(r.message())).toList().toString());
            assertEquals(5, w.anchorIndex(), "the anchor row is still the program's command");
            assertEquals(3_000, w.rows().get(w.anchorIndex()).message().timeNanos());
        }
    }
}
