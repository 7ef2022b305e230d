package org.stagecraft.spy.bench;

import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.stagecraft.recording.peers.ReplayPeer;

/**
 * The relay benchmark: the same load of recorded Player sessions (many concurrent connections, each
 * peer replaying its side as fast as the sockets take it) through a direct connection, socat and
 * the spy with decode+bus+log, in one run on one machine. Reports throughput, and round-trip
 * latency of a Player request/reply, idle and under that load; "added" is relay minus direct.
 * Every replayed byte is checked on both sides, so a fast but wrong relay fails instead of winning.
 *
 * <pre>java -jar spy-bench.jar [--sessions 6] [--clients 4] [--repeat 16] [--rounds 3] [--pings 5000]</pre>
 */
public final class RelayBench {
    private RelayBench() {
    }

    private record RunResult(double bytesPerSecond, double[] idleRtts, double[] loadedRtts) {
    }

    public static void main(String[] args) throws Exception {
        Map<String, Integer> opt = new LinkedHashMap<>(Map.of("sessions", 6, "clients", 4, "repeat", 16, "rounds", 3, "pings", 5000));
        for (int i = 0; i + 1 < args.length; i += 2) {
            String k = args[i].replaceFirst("^--", "");
            if (!opt.containsKey(k)) {
                throw new IllegalArgumentException("unknown option " + args[i] + " (known: " + opt.keySet() + ")");
            }
            opt.put(k, Integer.parseInt(args[i + 1]));
        }
        Workload w = Workload.load(opt.get("sessions"), opt.get("repeat"));
        int connections = opt.get("sessions") * opt.get("clients");
        System.out.printf("machine: %d cores, %s %s; socat %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name"), System.getProperty("java.version"), socatVersion());
        System.out.printf("load: %d ports x %d clients = %d concurrent connections, %.1f MB per run (both directions),"
                + " recorded Player sessions replayed as fast as the peers can%n", opt.get("sessions"), opt.get("clients"),
                connections, w.bytes() * opt.get("clients") / 1e6);
        Path logDir = Files.createTempDirectory("stagecraft-bench");
        List<Relay> relays = List.of(new DirectConnection(), new SocatRelay(), new SpyRelay(logDir, SpyServer.Depth.RELAY),
                new SpyRelay(logDir, SpyServer.Depth.BUS), new SpyRelay(logDir, SpyServer.Depth.LOG));
        Map<String, List<RunResult>> results = new LinkedHashMap<>();
        for (int round = 0; round < opt.get("rounds"); round++) {
            for (int k = 0; k < relays.size(); k++) {
                Relay relay = relays.get((k + round) % relays.size()); // rotate so no relay always runs first
                RunResult r = run(relay, w, opt.get("clients"), opt.get("pings"));
                results.computeIfAbsent(relay.name(), x -> new ArrayList<>()).add(r);
                System.out.printf("  round %d %-22s %8.1f MB/s  %s%n", round + 1, relay.name(), r.bytesPerSecond() / 1e6,
                        relay.report());
            }
        }
        Files.deleteIfExists(logDir);
        report(results);
    }

    private static RunResult run(Relay relay, Workload w, int clients, int pings) throws Exception {
        try (RecordedPlayers players = new RecordedPlayers(w); relay;
                ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor()) {
            List<InetSocketAddress> fronts = relay.start(players.addresses());
            InetSocketAddress pingAt = fronts.get(fronts.size() - 1);
            warmUp(fronts, w, players, peers);
            double[] idle = PingProbe.run(pingAt, w, pings, () -> true).sortedMicros();

            CountDownLatch go = new CountDownLatch(1);
            List<Future<ReplayPeer.Result>> programs = new ArrayList<>();
            for (int s = 0; s < w.sessions().size(); s++) {
                InetSocketAddress at = fronts.get(s);
                var session = w.sessions().get(s);
                for (int c = 0; c < clients; c++) {
                    programs.add(peers.submit(() -> {
                        go.await();
                        return ReplayPeer.client(new Socket(at.getAddress(), at.getPort()), session);
                    }));
                }
            }
            AtomicBoolean loaded = new AtomicBoolean(true);
            Future<PingProbe.Rtts> underLoad = Executors.newSingleThreadExecutor(Thread.ofPlatform().daemon().factory())
                    .submit(() -> PingProbe.run(pingAt, w, 1_000_000, loaded::get));
            long t0 = System.nanoTime();
            go.countDown();
            for (Future<ReplayPeer.Result> p : programs) {
                ReplayPeer.Result r = p.get(300, TimeUnit.SECONDS);
                if (!r.matches()) {
                    throw new IllegalStateException(relay.name() + ": a program received other bytes than recorded, from byte "
                            + r.firstDifference());
                }
            }
            long elapsed = System.nanoTime() - t0;
            loaded.set(false);
            double[] busy = underLoad.get(60, TimeUnit.SECONDS).sortedMicros();
            players.verifyServed(programs.size());
            return new RunResult(w.bytes() * clients / (elapsed / 1e9), idle, busy);
        }
    }

    /**
     * One short pass of every session so that a relay running in a fresh JVM is compiled before it is
     * measured: a JIT warming up would otherwise show as relay latency.
     */
    private static void warmUp(List<InetSocketAddress> fronts, Workload w, RecordedPlayers players, ExecutorService peers)
            throws Exception {
        List<Future<ReplayPeer.Result>> runs = new ArrayList<>();
        for (int s = 0; s < w.warmUp().size(); s++) {
            InetSocketAddress at = fronts.get(w.sessions().size() + s);
            var session = w.warmUp().get(s);
            runs.add(peers.submit(() -> ReplayPeer.client(new Socket(at.getAddress(), at.getPort()), session)));
        }
        for (Future<ReplayPeer.Result> r : runs) {
            if (!r.get(300, TimeUnit.SECONDS).matches()) {
                throw new IllegalStateException("warm-up: a program received other bytes than recorded");
            }
        }
        players.verifyServed(runs.size());
        PingProbe.run(fronts.get(fronts.size() - 1), w, 5_000, () -> true);
    }

    private static void report(Map<String, List<RunResult>> results) {
        System.out.println();
        System.out.println("| relay | throughput MB/s (median of rounds) | RTT idle p50 / p99 µs | added idle p50 / p99 µs"
                + " | RTT under load p50 / p99 µs | added under load p50 / p99 µs |");
        System.out.println("|---|---|---|---|---|---|");
        double[] base = null;
        for (Map.Entry<String, List<RunResult>> e : results.entrySet()) {
            List<RunResult> runs = e.getValue();
            double[] tput = runs.stream().mapToDouble(RunResult::bytesPerSecond).sorted().toArray();
            PingProbe.Rtts idle = new PingProbe.Rtts(merge(runs, true));
            PingProbe.Rtts busy = new PingProbe.Rtts(merge(runs, false));
            double[] q = {idle.quantile(0.5), idle.quantile(0.99), busy.quantile(0.5), busy.quantile(0.99)};
            if (base == null) {
                base = q;
            }
            System.out.printf("| %s | %.1f | %.1f / %.1f | %s | %.1f / %.1f (%d samples) | %s |%n", e.getKey(),
                    tput[tput.length / 2] / 1e6, q[0], q[1], added(q[0] - base[0], q[1] - base[1], e.getKey()), q[2], q[3],
                    busy.count(), added(q[2] - base[2], q[3] - base[3], e.getKey()));
        }
    }

    private static String added(double p50, double p99, String name) {
        return "direct".equals(name) ? "—" : String.format("%+.1f / %+.1f", p50, p99);
    }

    private static double[] merge(List<RunResult> runs, boolean idle) {
        double[] all = runs.stream().flatMapToDouble(r -> Arrays.stream(idle ? r.idleRtts() : r.loadedRtts())).toArray();
        Arrays.sort(all);
        return all;
    }

    private static String socatVersion() {
        try {
            Process p = new ProcessBuilder("socat", "-V").redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes());
            p.waitFor();
            return out.lines().filter(l -> l.contains("socat version")).findFirst().orElse("?").replaceAll(".*socat version ", "")
                    .replaceAll(" on .*", "");
        } catch (Exception e) {
            return "not found";
        }
    }
}
