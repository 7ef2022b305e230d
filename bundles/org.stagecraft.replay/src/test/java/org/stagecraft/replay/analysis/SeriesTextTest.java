package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.streams.StreamPattern;

class SeriesTextTest {
    @Test
    void threeWaysToWriteASeries() {
        assertArrayEquals(new String[] { "position2d", "pos.px" }, SeriesText.split("position2d.pos.px"));
        assertArrayEquals(new String[] { "ranger:1", "min(ranges)" }, SeriesText.split(" ranger:1  min(ranges) "));
        assertArrayEquals(new String[] { "laser:0", "mean( ranges )" }, SeriesText.split("laser:0 mean( ranges )"));
        assertArrayEquals(new String[] { "position2d:0 DATA", "pos.px" }, SeriesText.split("position2d:0 DATA pos.px"));
        assertArrayEquals(new String[] { "type=1 dev=4 index=*", "pos.px" }, SeriesText.split("type=1 dev=4 index=* | pos.px"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> SeriesText.split("position2d")).getMessage()
                .contains("names no field"));
        assertThrows(IllegalArgumentException.class, () -> SeriesText.split("laser | "));
    }

    @Test
    void aSpecFromTextPlotsTheRecordedPose() throws Exception {
        SeriesSpec s = SeriesText.spec("position2d.pos.px", ListLog.REGISTRY);
        assertEquals("position2d.pos.px", s.label());
        assertEquals(StreamPattern.any().deviceType(4).messageType(1), s.streams());
        ListLog log = AnalysisTestTraces.pioneer();
        Series px = SeriesSampler.sample(log, List.of(s), log.startNanos(), log.endNanos(), 50, () -> false).get(0);
        long expected = log.messages().stream().filter(m -> m.decoded() != null && s.streams().matches(MessageFilter.key(m).orElseThrow())
                && ScalarField.of(m.decoded().body(), "pos.px").isPresent()).count();
        assertEquals(expected, px.matched());
        assertTrue(px.size() > 0);
    }
}
