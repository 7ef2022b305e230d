package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.streams.StreamKey;

class TimelineDensityTest {
    private final MessageColumns columns = new MessageColumns(ListLog.REGISTRY);

    @Test
    void oneTrackPerStreamWithItsMessagesInTheirBuckets() throws Exception {
        ListLog log = AnalysisTestTraces.pioneer();
        List<Double> progress = new ArrayList<>();
        TimelineDensity d = TimelineDensity.scan(log, 100, columns, progress::add, () -> false);
        TimelineDensity.Snapshot s = d.snapshot();
        assertEquals(log.messages().size(), s.messages());
        assertEquals(1.0, progress.get(progress.size() - 1));

        Map<StreamKey, int[]> expected = new HashMap<>();
        int events = 0;
        for (LogMessage m : log.messages()) {
            var key = MessageFilter.key(m);
            if (key.isPresent()) {
                expected.computeIfAbsent(key.get(), k -> new int[100])[d.bucketOf(m.timeNanos())]++;
            } else {
                events++;
            }
        }
        assertTrue(expected.size() > 10, "streams in the recording: " + expected.size());
        assertEquals(expected.size() + 1, s.tracks().size(), "a track per stream and one for the banners");
        for (TimelineDensity.Track t : s.tracks()) {
            if (t.key() == null) {
                assertEquals(TimelineDensity.EVENTS, t.label());
                assertEquals(events, t.total());
            } else {
                assertTrue(java.util.Arrays.equals(expected.get(t.key()), t.counts()), t.label());
            }
        }
        TimelineDensity.Track laser = s.tracks().stream().filter(t -> t.label().equals("laser:0 DATA SCAN (#1 s2c)"))
                .findFirst().orElseThrow(() -> new AssertionError(s.tracks().stream().map(TimelineDensity.Track::label).toList()));
        assertTrue(laser.max() > 0 && laser.total() > 200);
        assertEquals(0, java.util.Arrays.stream(s.problems()).sum(), "the recording decodes cleanly");
        assertEquals(0, java.util.Arrays.stream(s.gaps()).sum());
        assertTrue(s.tracks().get(s.tracks().size() - 1).key() == null, "events last");
    }

    @Test
    void bucketsCoverTheRangeEdgeToEdge() {
        TimelineDensity d = new TimelineDensity(1_000, 2_000, 10, columns);
        assertEquals(0, d.bucketOf(0));
        assertEquals(0, d.bucketOf(1_099));
        assertEquals(1, d.bucketOf(1_100));
        assertEquals(9, d.bucketOf(2_000));
        assertEquals(9, d.bucketOf(5_000));
        assertEquals(1_500, d.bucketStart(5));
    }

    @Test
    void problemsAndGapsAreCountedWhereTheyHappen() {
        TimelineDensity d = new TimelineDensity(0, 100, 10, columns);
        var c = ListLog.connection(1, 6665);
        d.add(new LogMessage(55, c, Direction.SERVER_TO_CLIENT, -1, LogMessage.Kind.DIAGNOSTIC, null, null, "bad"), 0);
        d.add(new LogMessage(95, c, Direction.SERVER_TO_CLIENT, 7, LogMessage.Kind.UNFRAMED, new byte[3], null, ""), 12);
        TimelineDensity.Snapshot s = d.snapshot();
        assertEquals(1, s.problems()[5]);
        assertEquals(1, s.problems()[9]);
        assertEquals(1, s.gaps()[9]);
        assertEquals(1, s.tracks().size(), "the diagnostic is a mark, not a track; unframed bytes are on the events track");
    }

    @Test
    void streamsBeyondTheTrackLimitShareOne() {
        TimelineDensity d = new TimelineDensity(0, 100, 4, columns);
        LogMessage scan = AnalysisTestTraces.pioneer().messages().stream()
                .filter(m -> columns.device(m).equals("laser:0") && columns.type(m).equals("DATA")).findFirst().orElseThrow();
        for (int i = 1; i <= TimelineDensity.MAX_TRACKS + 10; i++) {
            d.add(new LogMessage(10, ListLog.connection(i, 6665), scan.dir(), scan.streamOffset(), scan.kind(), scan.bytes(),
                    scan.decoded(), ""), 0);
        }
        TimelineDensity.Snapshot s = d.snapshot();
        assertEquals(TimelineDensity.MAX_TRACKS, s.tracks().size());
        TimelineDensity.Track other = s.tracks().stream().filter(t -> t.label().equals(TimelineDensity.OTHER)).findFirst().orElseThrow();
        assertEquals(11, other.total());
    }
}
