package org.stagecraft.replay.analysis;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.function.BooleanSupplier;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.streams.StreamKey;

/**
 * Samples plot series from a log over a time range in one cursor pass: the range is cut into
 * {@code buckets} and each series keeps the lowest and the highest value of each bucket (min-max
 * thinning), so memory and drawing cost depend on the buckets, not on how many messages the range
 * holds.
 */
public final class SeriesSampler {
    private SeriesSampler() {
    }

    /** One series' thinning state. */
    private static final class Buckets {
        final long[] minT, maxT;
        final double[] min, max;
        long matched;

        Buckets(int n) {
            minT = new long[n];
            maxT = new long[n];
            min = new double[n];
            max = new double[n];
            java.util.Arrays.fill(min, Double.NaN);
            java.util.Arrays.fill(max, Double.NaN);
        }

        void add(int b, long t, double v) {
            matched++;
            if (Double.isNaN(min[b]) || v < min[b]) {
                min[b] = v;
                minT[b] = t;
            }
            if (Double.isNaN(max[b]) || v > max[b]) {
                max[b] = v;
                maxT[b] = t;
            }
        }

        /** One sample in the bucket (or all equal at one time): drawn once. */
        boolean single(int b) {
            return minT[b] == maxT[b] && min[b] == max[b];
        }

        Series toSeries(SeriesSpec spec) {
            int n = 0;
            for (int b = 0; b < min.length; b++) {
                if (!Double.isNaN(min[b])) {
                    n += single(b) ? 1 : 2;
                }
            }
            long[] times = new long[n];
            double[] values = new double[n];
            int i = 0;
            for (int b = 0; b < min.length; b++) {
                if (Double.isNaN(min[b])) {
                    continue;
                }
                if (single(b)) {
                    times[i] = minT[b];
                    values[i++] = min[b];
                    continue;
                }
                boolean minFirst = minT[b] <= maxT[b];
                times[i] = minFirst ? minT[b] : maxT[b];
                values[i++] = minFirst ? min[b] : max[b];
                times[i] = minFirst ? maxT[b] : minT[b];
                values[i++] = minFirst ? max[b] : min[b];
            }
            return new Series(spec, times, values, matched);
        }
    }

    /**
     * Samples {@code specs} over {@code [from, to]}.
     *
     * @param cancelled asked now and then; when it says yes, sampling stops and what was read so far is returned
     */
    public static List<Series> sample(SessionLog log, List<SeriesSpec> specs, long from, long to, int buckets,
            BooleanSupplier cancelled) throws IOException {
        if (buckets < 1) {
            throw new IllegalArgumentException("buckets " + buckets + " < 1");
        }
        long end = Math.max(from, to);
        double span = Math.max(1, end - from);
        List<Buckets> state = new ArrayList<>();
        for (int i = 0; i < specs.size(); i++) {
            state.add(new Buckets(buckets));
        }
        if (!specs.isEmpty()) {
            try (LogCursor c = log.cursor(from)) {
                long n = 0;
                for (LogMessage m = c.next(); m != null && m.timeNanos() <= end; m = c.next()) {
                    if ((++n & 1023) == 0 && cancelled.getAsBoolean()) {
                        break;
                    }
                    if (m.kind() != LogMessage.Kind.FRAME || m.decoded() == null || m.decoded().hasProblem()) {
                        continue;
                    }
                    Optional<StreamKey> k = MessageFilter.key(m);
                    if (k.isEmpty()) {
                        continue;
                    }
                    StreamKey key = k.get();
                    MessageBody body = m.decoded().body();
                    int b = (int) Math.min(buckets - 1, (m.timeNanos() - from) / span * buckets);
                    for (int i = 0; i < specs.size(); i++) {
                        SeriesSpec s = specs.get(i);
                        if (s.streams().matches(key)) {
                            OptionalDouble v = s.value().apply(body);
                            if (v.isPresent() && !Double.isNaN(v.getAsDouble())) {
                                state.get(i).add(b, m.timeNanos(), v.getAsDouble());
                            }
                        }
                    }
                }
            }
        }
        List<Series> out = new ArrayList<>();
        for (int i = 0; i < specs.size(); i++) {
            out.add(state.get(i).toSeries(specs.get(i)));
        }
        return out;
    }
}
