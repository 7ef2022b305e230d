package org.stagecraft.replay.analysis;

import java.util.Iterator;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.TreeMap;

import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.Subscription;

/**
 * A plot series recorded from a bus as the replay publishes: for derived streams (user message types,
 * 128 and up), which stream processors compute on the replay's bus and no log holds. Takes only
 * user-defined streams (logged ones are sampled from the log). The value is the payload itself when
 * it is a number, else the series' field path applied to the body ({@link MessageBody} or the
 * {@link SpyMessage}'s). Memory is bounded: past {@code capacity} points every second one is dropped,
 * so the series keeps its shape at half the resolution.
 */
public final class RecordedSeries implements AutoCloseable {
    public static final int DEFAULT_CAPACITY = 4096;

    private final SeriesSpec spec;
    private final int capacity;
    private final TreeMap<Long, Double> points = new TreeMap<>();
    private final Subscription subscription;
    private long received, version;

    public RecordedSeries(SeriesSpec spec, StreamBus bus, int capacity) {
        if (capacity < 2) {
            throw new IllegalArgumentException("capacity " + capacity + " < 2");
        }
        this.spec = spec;
        this.capacity = capacity;
        this.subscription = bus.subscribe(spec.streams(), DeliveryPolicy.lossless(1 << 14), this::accept);
    }

    /** Takes one message (the bus consumer). */
    public void accept(StreamMessage m) {
        if (!m.key().isUserDefined()) {
            return;
        }
        OptionalDouble v = value(m.payload());
        if (v.isEmpty() || Double.isNaN(v.getAsDouble())) {
            return;
        }
        synchronized (this) {
            received++;
            version++;
            points.put(m.timeNanos(), v.getAsDouble());
            if (points.size() > capacity) {
                thin();
            }
        }
    }

    private OptionalDouble value(Object payload) {
        if (payload instanceof Number n) {
            return OptionalDouble.of(n.doubleValue());
        }
        if (payload instanceof SpyMessage s && s.message() != null && s.message().body() != null) {
            return spec.value().apply(s.message().body());
        }
        if (payload instanceof MessageBody b) {
            return spec.value().apply(b);
        }
        return OptionalDouble.empty();
    }

    private void thin() {
        boolean drop = false;
        for (Iterator<Long> it = points.keySet().iterator(); it.hasNext();) {
            it.next();
            if (drop) {
                it.remove();
            }
            drop = !drop;
        }
    }

    /** Changes with every point taken, so a view redraws only when there is something new. */
    public synchronized long version() {
        return version;
    }

    /** The points between {@code from} and {@code to} (inclusive), with the number of values received in all. */
    public synchronized Series snapshot(long from, long to) {
        Map<Long, Double> range = points.subMap(from, true, to, true);
        long[] t = new long[range.size()];
        double[] v = new double[range.size()];
        int i = 0;
        for (Map.Entry<Long, Double> e : range.entrySet()) {
            t[i] = e.getKey();
            v[i++] = e.getValue();
        }
        return new Series(spec, t, v, received);
    }

    @Override
    public void close() {
        subscription.close();
    }
}
