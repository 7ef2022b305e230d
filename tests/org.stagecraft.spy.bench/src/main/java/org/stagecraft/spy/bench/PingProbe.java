package org.stagecraft.spy.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.Arrays;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.BooleanSupplier;

/**
 * Round trips of one real Player request and reply through a relay, one at a time, timed with
 * {@link System#nanoTime()}: what a PULL-mode robot program waits for on every cycle.
 */
final class PingProbe {
    static final int WARMUP = 200;

    /** Round-trip times in microseconds, sorted. */
    record Rtts(double[] sortedMicros, int pings) {
        Rtts(double[] sortedMicros) {
            this(sortedMicros, sortedMicros.length + WARMUP);
        }

        double quantile(double q) {
            if (sortedMicros.length == 0) {
                return Double.NaN;
            }
            int i = (int) Math.min(sortedMicros.length - 1, Math.round(q * (sortedMicros.length - 1)));
            return sortedMicros[i];
        }

        int count() {
            return sortedMicros.length;
        }
    }

    /** Pings running on a thread of their own while a workload plays; {@link #stop()} ends them. */
    static final class Background {
        private final AtomicBoolean running = new AtomicBoolean(true);
        private final Future<Rtts> pings;

        private Background(InetSocketAddress at, Workload w, long intervalNanos) {
            ExecutorService one = Executors.newSingleThreadExecutor(Thread.ofPlatform().daemon().factory());
            pings = one.submit(() -> run(at, w, 1_000_000, running::get, intervalNanos));
            one.shutdown();
        }

        /** Stops pinging; the round trips so far. */
        Rtts stop() throws Exception {
            running.set(false);
            return pings.get(60, TimeUnit.SECONDS);
        }
    }

    /** Starts pinging in the background, one every {@code intervalNanos} at most (0: back to back). */
    static Background inBackground(InetSocketAddress at, Workload w, long intervalNanos) {
        return new Background(at, w, intervalNanos);
    }

    /** Pings at most {@code max} times after a warm-up, and stops early once {@code more} says so. */
    static Rtts run(InetSocketAddress at, Workload w, int max, BooleanSupplier more) throws IOException {
        return run(at, w, max, more, 0);
    }

    /**
     * Pings at most {@code max} times after a warm-up, one every {@code intervalNanos} at most (0: back
     * to back), and stops early once {@code more} says so.
     */
    static Rtts run(InetSocketAddress at, Workload w, int max, BooleanSupplier more, long intervalNanos) throws IOException {
        try (Socket s = new Socket()) {
            s.setTcpNoDelay(true);
            s.connect(at);
            InputStream in = s.getInputStream();
            OutputStream out = s.getOutputStream();
            if (in.readNBytes(w.banner().length).length != w.banner().length) {
                throw new IOException("no banner from " + at);
            }
            byte[] reply = new byte[w.pingReply().length];
            double[] rtts = new double[max];
            int n = 0;
            long next = System.nanoTime();
            for (int i = 0; i < WARMUP + max && (i < WARMUP || more.getAsBoolean()); i++) {
                if (intervalNanos > 0 && i >= WARMUP) {
                    next += intervalNanos;
                    for (long wait = next - System.nanoTime(); wait > 0; wait = next - System.nanoTime()) {
                        java.util.concurrent.locks.LockSupport.parkNanos(wait);
                    }
                }
                long t0 = System.nanoTime();
                out.write(w.pingRequest());
                if (in.readNBytes(reply, 0, reply.length) != reply.length) {
                    throw new IOException("the reply was cut short");
                }
                long t1 = System.nanoTime();
                if (i >= WARMUP) {
                    rtts[n++] = (t1 - t0) / 1e3;
                }
            }
            double[] sorted = Arrays.copyOf(rtts, n);
            Arrays.sort(sorted);
            return new Rtts(sorted, WARMUP + n);
        }
    }
}
