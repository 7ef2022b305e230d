package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.codec.DecodeProblem;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.log.LogMessage;

class MessageColumnsTest {
    private final MessageColumns columns = new MessageColumns(ListLog.REGISTRY);

    private LogMessage first(String device, String type, String subtype) {
        return AnalysisTestTraces.pioneer().messages().stream()
                .filter(m -> columns.device(m).equals(device) && columns.type(m).equals(type)
                        && columns.subtype(m).equals(subtype))
                .findFirst().orElseThrow(() -> new AssertionError("no " + device + " " + type + " " + subtype));
    }

    @Test
    void positionDataShowsItsPoseAndSpeed() {
        LogMessage m = first("position2d:0", "DATA", "STATE");
        String[] row = columns.row(m, AnalysisTestTraces.pioneer().startNanos());
        assertEquals(MessageColumns.TITLES.length, row.length);
        assertEquals("s2c", row[2]);
        assertEquals(Integer.toString(m.bytes().length), row[6]);
        String s = row[7];
        assertTrue(s.startsWith("pos.px="), s);
        assertTrue(s.contains(" pos.py=") && s.contains(" pos.pa=") && s.contains(" vel.px=") && s.contains(" stall="), s);
        double px = ScalarField.of(m.decoded().body(), "pos.px").getAsDouble();
        assertTrue(s.contains("pos.px=" + MessageSummary.number(px) + " "), s + " vs " + px);
    }

    @Test
    void aLaserScanShowsItsRangesAsCountAndSpan() {
        LogMessage m = first("laser:0", "DATA", "SCAN");
        String s = columns.summary(m);
        var count = new int[1];
        var lo = new double[] { Double.POSITIVE_INFINITY };
        var hi = new double[] { Double.NEGATIVE_INFINITY };
        m.decoded().body().describe(new RangesProbe(count, lo, hi));
        assertTrue(count[0] > 100, "a real scan: " + count[0]);
        assertTrue(s.contains("ranges[" + count[0] + "] " + MessageSummary.number(lo[0]) + ".." + MessageSummary.number(hi[0])), s);
        assertTrue(s.length() <= MessageSummary.MAX_LENGTH, s);
    }

    @Test
    void bannersEventsAndProblemsSayWhatTheyAre() {
        LogMessage banner = AnalysisTestTraces.pioneer().messages().get(0);
        assertEquals(LogMessage.Kind.BANNER, banner.kind());
        assertEquals("banner \"Player v.3.1.1-dev\"", columns.summary(banner));
        assertEquals("BANNER", columns.type(banner));
        assertEquals("", columns.device(banner));

        LogMessage frame = first("laser:0", "DATA", "SCAN");
        LogMessage broken = new LogMessage(frame.timeNanos(), frame.connection(), Direction.SERVER_TO_CLIENT, 0,
                LogMessage.Kind.FRAME, frame.bytes(), new DecodedMessage(frame.decoded().header(), frame.decoded().body(),
                        new DecodeProblem(12, "ranges_count 9999 exceeds the payload")), "");
        assertEquals("decode problem at payload byte 12: ranges_count 9999 exceeds the payload", columns.summary(broken));

        LogMessage opened = new LogMessage(0, ListLog.connection(3, 6665), null, -1, LogMessage.Kind.OPENED, null, null, "");
        assertEquals("connection opened: 127.0.0.1:40003 to 127.0.0.1:6665 (relayed to 127.0.0.1:7665)", columns.summary(opened));
        assertEquals("#3 127.0.0.1:40003", columns.connection(opened));
        assertEquals("", columns.direction(opened));
    }

    @Test
    void numbersAreShortButExactForIntegers() {
        assertEquals("3", MessageSummary.number(3.0));
        assertEquals("-0.25", MessageSummary.number(-0.25));
        assertEquals("1.2346", MessageSummary.number(1.23456789));
        assertEquals("1.000e-04", MessageSummary.number(0.0001));
        assertEquals("NaN", MessageSummary.number(Double.NaN));
        assertEquals(List.of("12.500000"), List.of(MessageColumns.time(13_500_000_000L, 1_000_000_000L)));
    }

    /** The top-level "ranges" list of a scan. */
    private record RangesProbe(int[] count, double[] lo, double[] hi) implements org.stagecraft.player.codec.FieldVisitor {
        static boolean inRanges;

        @Override
        public void integer(String name, long value) {
        }

        @Override
        public void float32(String name, float value) {
            if (inRanges && name == null) {
                count[0]++;
                lo[0] = Math.min(lo[0], value);
                hi[0] = Math.max(hi[0], value);
            }
        }

        @Override
        public void float64(String name, double value) {
        }

        @Override
        public void text(String name, String value) {
        }

        @Override
        public void opaque(String name, byte[] value) {
        }

        @Override
        public void beginStruct(String name) {
        }

        @Override
        public void endStruct() {
        }

        @Override
        public void beginList(String name) {
            inRanges = "ranges".equals(name);
        }

        @Override
        public void endList() {
            inRanges = false;
        }
    }
}
