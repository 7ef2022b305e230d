package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.stagecraft.replay.log.LogMessage;

class SeriesSamplerTest {
    private final ListLog log = AnalysisTestTraces.pioneer();
    private final SeriesSpec px = new SeriesSpec("position2d:0 pos.px", StreamSelector.parse("position2d:0", ListLog.REGISTRY),
            b -> ScalarField.of(b, "pos.px"));
    private final SeriesSpec pa = new SeriesSpec("position2d:0 pos.pa", StreamSelector.parse("position2d:0", ListLog.REGISTRY),
            b -> ScalarField.of(b, "pos.pa"));

    private List<double[]> truth(SeriesSpec s, long from, long to) {
        return log.messages().stream()
                .filter(m -> m.timeNanos() >= from && m.timeNanos() <= to && m.kind() == LogMessage.Kind.FRAME)
                .filter(m -> s.streams().matches(MessageFilter.key(m).orElseThrow()))
                .map(m -> new double[] { m.timeNanos(), s.value().apply(m.decoded().body()).orElse(Double.NaN) })
                .filter(p -> !Double.isNaN(p[1])).toList();
    }

    @Test
    void thinnedToTwoPointsABucketKeepingEveryBucketsExtremes() throws Exception {
        long from = log.startNanos(), to = log.endNanos();
        List<Series> out = SeriesSampler.sample(log, List.of(px, pa), from, to, 20, () -> false);
        assertEquals(2, out.size());
        for (Series s : out) {
            List<double[]> all = truth(s.spec(), from, to);
            assertTrue(all.size() > 100, "position data in the recording: " + all.size());
            assertEquals(all.size(), s.matched());
            assertTrue(s.size() <= 40 && s.size() >= 20, "points: " + s.size());
            double lo = all.stream().mapToDouble(p -> p[1]).min().orElseThrow();
            double hi = all.stream().mapToDouble(p -> p[1]).max().orElseThrow();
            assertEquals(lo, s.range()[0], s.spec().label());
            assertEquals(hi, s.range()[1], s.spec().label());
            assertTrue(hi > lo, "the robot moved");
            for (int i = 1; i < s.size(); i++) {
                assertTrue(s.times()[i] >= s.times()[i - 1], "in time order");
            }
            for (int i = 0; i < s.size(); i++) {
                long t = s.times()[i];
                double v = s.values()[i];
                assertTrue(all.stream().anyMatch(p -> p[0] == t && p[1] == v), "every point is a real sample");
            }
        }
    }

    @Test
    void aShortRangeKeepsEverySample() throws Exception {
        long mid = (log.startNanos() + log.endNanos()) / 2, to = mid + 1_000_000_000L;
        List<double[]> all = truth(px, mid, to);
        Series s = SeriesSampler.sample(log, List.of(px), mid, to, 10_000, () -> false).get(0);
        assertEquals(all.size(), s.size(), "each sample alone in its bucket, drawn once");
        assertEquals(all.get(0)[1], s.valueAt((long) all.get(0)[0]));
        assertTrue(Double.isNaN(s.valueAt(mid - 1)));
    }

    @Test
    void nothingMatchesNothingIsDrawn() throws Exception {
        SeriesSpec none = new SeriesSpec("laser nothing", StreamSelector.parse("laser", ListLog.REGISTRY), b -> ScalarField.of(b, "nope"));
        Series s = SeriesSampler.sample(log, List.of(none), log.startNanos(), log.endNanos(), 50, () -> false).get(0);
        assertEquals(0, s.size());
        assertTrue(Double.isNaN(s.range()[0]));
    }
}
