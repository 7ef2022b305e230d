package org.stagecraft.replay.analysis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.OptionalDouble;

import org.junit.jupiter.api.Test;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

class RecordedSeriesTest {
    private static final StreamKey DERIVED = new StreamKey("127.0.0.1:6665", "127.0.0.1:40001", 128, 62, 0, 1);
    private final SeriesSpec spec = new SeriesSpec("mean sonar", StreamPattern.any().deviceType(62), b -> OptionalDouble.empty());

    @Test
    void takesNumbersOfDerivedStreamsOnlyInTimeOrder() throws Exception {
        try (StreamBus bus = new StreamBus(Runnable::run); RecordedSeries r = new RecordedSeries(spec, bus, 100)) {
            bus.publish(new StreamMessage(DERIVED, 30, 3.0));
            bus.publish(new StreamMessage(DERIVED, 10, 1.0)); // after a seek back
            bus.publish(new StreamMessage(DERIVED.withMessageType(1), 20, 2.0)); // a logged stream: sampled from the log instead
            bus.publish(new StreamMessage(DERIVED, 40, "not a number"));
            Series s = r.snapshot(0, 100);
            assertArrayEquals(new long[] { 10, 30 }, s.times());
            assertArrayEquals(new double[] { 1.0, 3.0 }, s.values());
            assertEquals(2, s.matched());
            assertEquals(1, r.snapshot(20, 30).size());
        }
    }

    @Test
    void staysWithinItsCapacityKeepingTheWholeSpan() {
        try (StreamBus bus = new StreamBus(Runnable::run); RecordedSeries r = new RecordedSeries(spec, bus, 64)) {
            for (int i = 0; i < 1000; i++) {
                r.accept(new StreamMessage(DERIVED, i, (double) i));
            }
            Series s = r.snapshot(Long.MIN_VALUE, Long.MAX_VALUE);
            assertTrue(s.size() <= 64 && s.size() >= 32, "points: " + s.size());
            assertEquals(0, s.times()[0], "the first point stays");
            assertTrue(s.times()[s.size() - 1] >= 1000 - 1000 / 32, "the span reaches the end: " + s.times()[s.size() - 1]);
            assertEquals(1000, s.matched());
        }
    }

    @Test
    void mergeInterleavesByTime() {
        Series a = new Series(spec, new long[] { 1, 5 }, new double[] { 1, 5 }, 2);
        Series b = new Series(spec, new long[] { 3 }, new double[] { 3 }, 1);
        Series m = a.merge(b);
        assertArrayEquals(new long[] { 1, 3, 5 }, m.times());
        assertArrayEquals(new double[] { 1, 3, 5 }, m.values());
        assertEquals(3, m.matched());
    }
}
