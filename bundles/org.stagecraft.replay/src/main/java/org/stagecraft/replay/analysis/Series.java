package org.stagecraft.replay.analysis;

/**
 * Sampled points of one series, in time order: at most two per bucket of the sampled range (the
 * bucket's lowest and highest value, in the order they occurred; one when they are the same sample), so a spike never disappears
 * however long the range.
 *
 * @param spec    what was sampled
 * @param times   log times in nanoseconds
 * @param values  the values at those times
 * @param matched how many messages in the range had a value (before thinning)
 */
public record Series(SeriesSpec spec, long[] times, double[] values, long matched) {

    /** This series' points and {@code other}'s (same spec) in one time order; counts add up. */
    public Series merge(Series other) {
        if (other.size() == 0) {
            return this;
        }
        if (size() == 0) {
            return new Series(spec, other.times, other.values, matched + other.matched);
        }
        long[] t = new long[size() + other.size()];
        double[] v = new double[t.length];
        int i = 0, j = 0, k = 0;
        while (i < size() || j < other.size()) {
            if (j >= other.size() || (i < size() && times[i] <= other.times[j])) {
                t[k] = times[i];
                v[k++] = values[i++];
            } else {
                t[k] = other.times[j];
                v[k++] = other.values[j++];
            }
        }
        return new Series(spec, t, v, matched + other.matched);
    }

    public int size() {
        return times.length;
    }

    /** Lowest and highest value, or {NaN, NaN} when empty. */
    public double[] range() {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (double v : values) {
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        return values.length == 0 ? new double[] { Double.NaN, Double.NaN } : new double[] { lo, hi };
    }

    /** The value of the last point at or before {@code t}, or NaN. */
    public double valueAt(long t) {
        int lo = 0, hi = times.length - 1, found = -1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            if (times[mid] <= t) {
                found = mid;
                lo = mid + 1;
            } else {
                hi = mid - 1;
            }
        }
        return found < 0 ? Double.NaN : values[found];
    }
}
