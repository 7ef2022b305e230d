package org.stagecraft.replay.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;

import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceFraming;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * How replay copes with a large spy log: builds one of about the given size from recorded traffic
 * (the headless PUSH session, about 1000 messages/s, repeated end to end as new connections with
 * shifted times), then measures opening it, seeking to random times, stepping back after a seek and
 * reading forward, and the heap in use. Run with a small heap to see that memory stays flat:
 * {@code ./stagecraft bench replay [--size-mb 1024] [--file PATH] [--seeks 200]}.
 */
public final class LargeLogBench {
    private static final String TRACE = "rates.headless-push.trace.jsonl";

    private LargeLogBench() {
    }

    private record Wire(long time, int conn, int port, SessionEvent event) {
    }

    public static void main(String[] args) throws Exception {
        long sizeMb = 1024;
        Path file = Path.of(System.getProperty("java.io.tmpdir"), "stagecraft-large-bench.mcap");
        int seeks = 200;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--size-mb" -> sizeMb = Long.parseLong(args[++i]);
                case "--file" -> file = Path.of(args[++i]);
                case "--seeks" -> seeks = Integer.parseInt(args[++i]);
                default -> throw new IllegalArgumentException("unknown option " + args[i]
                        + " (use --size-mb N, --file PATH, --seeks N)");
            }
        }
        if (!Files.exists(file) || Files.size(file) < sizeMb * 1024 * 1024 * 9 / 10) {
            generate(file, sizeMb * 1024 * 1024);
        } else {
            System.out.printf(Locale.ROOT, "reusing %s (%.0f MB)%n", file, Files.size(file) / 1e6);
        }
        measure(file, seeks);
    }

    private static void generate(Path file, long bytes) throws IOException {
        List<Wire> one = new ArrayList<>();
        List<long[]> lifecycle = new ArrayList<>(); // time, conn, port, open?1:0
        Path trace = TraceCorpus.file(TRACE);
        try (TraceReader r = new TraceReader(trace)) {
            TraceFraming.frame(r, e -> one.add(new Wire(Math.round(e.t() * 1e9), e.stream().conn(), e.stream().port(), e)),
                    l -> lifecycle.add(new long[] { Math.round(l.t() * 1e9), l.conn(), l.port(), l.isClose() ? 0 : 1 }));
        }
        long span = one.get(one.size() - 1).time() - one.get(0).time() + 1_000_000;
        int conns = (int) lifecycle.stream().mapToLong(l -> l[1]).max().orElse(1);
        long start = System.nanoTime();
        long messages = 0;
        int rep = 0;
        try (SpyLogWriter w = SpyLogWriter.create(file, Map.of("generated-by", "LargeLogBench", "from", TRACE))) {
            while (Files.size(file) < bytes) {
                long shift = rep * span;
                int connShift = rep * conns;
                for (long[] l : lifecycle) {
                    if (l[3] == 1) {
                        w.connectionOpened(l[0] + shift, (int) l[1] + connShift, "127.0.0.1:" + (40000 + l[1] + connShift),
                                "127.0.0.1:" + l[2], "127.0.0.1:" + (l[2] + 1000));
                    }
                }
                for (Wire x : one) {
                    w.wire(x.time() + shift, x.conn() + connShift, x.port(), x.event().stream().dir(), x.event().event());
                    messages++;
                }
                for (long[] l : lifecycle) {
                    if (l[3] == 0) {
                        w.connectionClosed(l[0] + shift, (int) l[1] + connShift, "closed (recorded)");
                    }
                }
                w.flush();
                rep++;
            }
        }
        double s = (System.nanoTime() - start) / 1e9;
        System.out.printf(Locale.ROOT, "generated %s: %.0f MB, %d wire messages, %d connections, %.1f s of log, in %.1f s%n",
                file, Files.size(file) / 1e6, messages, rep * conns, rep * span / 1e9, s);
    }

    private static void measure(Path file, int seeks) throws IOException {
        long heapBefore = usedHeap();
        long t0 = System.nanoTime();
        try (SessionLog log = SessionLogs.open(file)) {
            double openMs = (System.nanoTime() - t0) / 1e6;
            long heapOpen = usedHeap();
            System.out.printf(Locale.ROOT, "open: %.1f ms (%d wire messages, %d connections, %.1f s of log, problems %s)%n",
                    openMs, log.messageCount(), log.connections().size(), (log.endNanos() - log.startNanos()) / 1e9,
                    log.problems());
            Random random = new Random(7);
            double[] seekMs = new double[seeks];
            double[] backMs = new double[seeks];
            long span = log.endNanos() - log.startNanos();
            try (LogCursor c = log.cursor(log.startNanos())) {
                for (int i = 0; i < seeks; i++) {
                    long t = log.startNanos() + (long) (random.nextDouble() * span);
                    long a = System.nanoTime();
                    c.seek(t);
                    LogMessage m = c.next();
                    long b = System.nanoTime();
                    c.previous();
                    LogMessage back = c.previous();
                    long d = System.nanoTime();
                    if (m == null || m.timeNanos() < t || (back != null && back.timeNanos() > m.timeNanos())) {
                        throw new IllegalStateException("seek to " + t + " landed wrongly: " + m);
                    }
                    seekMs[i] = (b - a) / 1e6;
                    backMs[i] = (d - b) / 1e6;
                }
                long a = System.nanoTime();
                long n = 0;
                c.seek(log.startNanos() + span / 2);
                while (n < 1_000_000 && c.next() != null) {
                    n++;
                }
                double readS = (System.nanoTime() - a) / 1e9;
                System.out.printf(Locale.ROOT, "seek + first message (%d random seeks): %s%n", seeks, stats(seekMs));
                System.out.printf(Locale.ROOT, "two steps back after a seek: %s%n", stats(backMs));
                System.out.printf(Locale.ROOT, "read forward: %d messages (decoded) in %.2f s = %.0f msgs/s%n", n, readS,
                        n / readS);
            }
            System.out.printf(Locale.ROOT, "heap in use: %.1f MB before open, %.1f MB open, %.1f MB after seeking (max heap %.0f MB, file %.0f MB)%n",
                    heapBefore / 1e6, heapOpen / 1e6, usedHeap() / 1e6, Runtime.getRuntime().maxMemory() / 1e6,
                    Files.size(file) / 1e6);
        }
    }

    private static String stats(double[] ms) {
        double[] s = ms.clone();
        Arrays.sort(s);
        return String.format(Locale.ROOT, "median %.2f ms, p90 %.2f ms, p99 %.2f ms, max %.2f ms", s[s.length / 2],
                s[(int) (s.length * 0.9)], s[Math.min(s.length - 1, (int) (s.length * 0.99))], s[s.length - 1]);
    }

    private static long usedHeap() {
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }
}
