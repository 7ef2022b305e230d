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

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;

/**
 * The relay benchmark: the same recorded Player sessions through a direct connection, socat, the spy
 * as a relay only and the full spy (decode + bus + MCAP log, what {@code stagecraft spy --log}
 * runs), in one run on one machine, in two phases:
 * <ul>
 * <li><b>recorded pace</b>: six robots' sessions (one connection each) replayed at the times they
 * were recorded, both sides, as a real robot program and a real Player produce them, plus a robot
 * program pinging Player 100 times a second;</li>
 * <li><b>full speed</b>: many concurrent connections, each replaying its session (lengthened) as fast
 * as the sockets take it, plus a ping probe back to back.</li>
 * </ul>
 * For each relay: bytes forwarded but not observed (the spy's count; socat and the relay alone observe
 * nothing), CPU per Player message (the relay process's user + system time during the phase, socat's
 * forked children included, divided by the messages relayed), the round-trip time a Player request
 * and its reply add over a direct connection (p50 / p99 / p99.9), throughput at full speed and the
 * relay process's peak resident memory. Every replayed byte is checked on both sides, so a fast but
 * wrong relay fails instead of winning.
 *
 * <pre>java -jar spy-bench.jar [--sessions 6] [--clients 4] [--repeat 16] [--rounds 2] [--pings 5000]
 *     [--pace-seconds 15] [--bus 0] [--paced 1] [--full 1] [--others 1] [--paced-warmup 1]</pre>
 * ({@code --paced 0} or {@code --full 0} leaves a phase out, {@code --others 0} runs the full spy alone.)
 */
public final class RelayBench {
    private RelayBench() {
    }

    private record RunResult(double bytesPerSecond, double[] idleRtts, double[] loadedRtts, double cpuMicrosPerMessage,
            long unobserved, double peakRssMb, String cpuByThread) {
    }

    private enum Phase {
        PACED("recorded pace"), FULL("full speed");

        final String label;

        Phase(String label) {
            this.label = label;
        }
    }

    public static void main(String[] args) throws Exception {
        Map<String, Integer> opt = new LinkedHashMap<>(Map.of("sessions", 6, "clients", 4, "repeat", 16, "rounds", 2,
                "pings", 5000, "pace-seconds", 15, "bus", 0, "session", 1));
        opt.putAll(Map.of("paced", 1, "full", 1, "others", 1, "paced-warmup", 1));
        for (int i = 0; i + 1 < args.length; i += 2) {
            String k = args[i].replaceFirst("^--", "");
            if (!opt.containsKey(k)) {
                throw new IllegalArgumentException("unknown option " + args[i] + " (known: " + opt.keySet() + ")");
            }
            opt.put(k, Integer.parseInt(args[i + 1]));
        }
        Workload w = Workload.load(opt.get("sessions"), opt.get("repeat"));
        List<TimedSession> paced = TimedSession.load(opt.get("sessions"), opt.get("pace-seconds"));
        int clients = opt.get("clients");
        long fullMessages = messages(w) * clients;
        long pacedMessages = paced.stream().mapToLong(TimedSession::messages).sum();
        System.out.printf("machine: %d cores, %s %s; socat %s; load average %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.vm.name"), System.getProperty("java.version"), socatVersion(), loadAverage());
        System.out.printf("recorded pace: %d robots' sessions, %d s each, %d messages (%.0f msg/s), %.1f MB,"
                + " plus pings at 100/s%n", paced.size(), opt.get("pace-seconds"), pacedMessages,
                pacedMessages / (double) opt.get("pace-seconds"), paced.stream().mapToLong(TimedSession::totalBytes).sum() / 1e6);
        System.out.printf("full speed: %d ports x %d clients = %d concurrent connections, %d messages, %.1f MB per run"
                + " (both directions), as fast as the peers can%n", opt.get("sessions"), clients, opt.get("sessions") * clients,
                fullMessages, w.bytes() * clients / 1e6);
        Path logDir = Files.createTempDirectory("stagecraft-bench");
        // --others 0: the full spy alone (profiling); --paced 0 / --full 0: one phase only
        List<Relay> relays = new ArrayList<>(opt.get("others") == 0 ? List.of() : List.of(new DirectConnection(),
                new SocatRelay(), new SpyRelay(logDir, SpyServer.Depth.RELAY)));
        if (opt.get("bus") != 0) {
            relays.add(new SpyRelay(logDir, SpyServer.Depth.BUS));
        }
        relays.add(new SpyRelay(logDir, SpyServer.Depth.LOG));
        if (opt.get("session") != 0) {
            relays.add(new SpyRelay(logDir, SpyServer.Depth.SESSION));
        }
        Map<Phase, Map<String, List<RunResult>>> results = new LinkedHashMap<>();
        for (int round = 0; round < opt.get("rounds"); round++) {
            for (Phase phase : Phase.values()) {
                if (opt.get(phase == Phase.PACED ? "paced" : "full") == 0) {
                    continue;
                }
                for (int k = 0; k < relays.size(); k++) {
                    Relay relay = relays.get((k + round) % relays.size()); // rotate so no relay always runs first
                    RunResult r = phase == Phase.PACED ? runPaced(relay, paced, w, pacedMessages, opt.get("paced-warmup") != 0)
                            : runFull(relay, w, clients, opt.get("pings"), fullMessages);
                    results.computeIfAbsent(phase, x -> new LinkedHashMap<>())
                            .computeIfAbsent(relay.name(), x -> new ArrayList<>()).add(r);
                    System.out.printf("  round %d %-13s %-20s %8.1f MB/s %7.2f µs CPU/msg  %s%n", round + 1, phase.label,
                            relay.name(), r.bytesPerSecond() / 1e6, r.cpuMicrosPerMessage(), relay.report());
                    if (!r.cpuByThread().isEmpty()) {
                        System.out.printf("          CPU per message by thread: %s%n", r.cpuByThread());
                    }
                }
            }
        }
        Files.deleteIfExists(logDir);
        for (Phase phase : results.keySet()) {
            report(phase, results.get(phase));
        }
    }

    /** Six robots at their recorded pace, one connection each, and a robot program pinging 100 times a second. */
    private static RunResult runPaced(Relay relay, List<TimedSession> sessions, Workload w, long sessionMessages,
            boolean pacedWarmUp) throws Exception {
        double cpu;
        double rss;
        Map<String, Double> threads;
        double[] rtts;
        int pings;
        long t0;
        long elapsed;
        try (PacedPlayers players = new PacedPlayers(sessions, w); RecordedPlayers fast = new RecordedPlayers(w); relay;
                ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor()) {
            List<InetSocketAddress> upstreams = new ArrayList<>(players.addresses());
            upstreams.addAll(fast.addresses());
            List<InetSocketAddress> all = relay.start(upstreams);
            List<InetSocketAddress> fronts = all.subList(0, players.addresses().size());
            // every session fast, several times over, so that the JIT has compiled the relay's paths before the
            // measured window (at this pace a compilation in the window would weigh more than the messages)
            for (int pass = 0; pass < 10; pass++) {
                warmUp(all.subList(fronts.size(), all.size()), w, fast, peers);
            }
            InetSocketAddress pingAt = fronts.get(fronts.size() - 1);
            if (pacedWarmUp) {
                // and once at the recorded pace: a relay that sleeps between messages takes other paths (parking,
                // waking, small batches) than the fast passes, and the JIT compiles those too (seen: ~9 µs of
                // compiler time per message in the window without this pass)
                PingProbe.Background warmPings = PingProbe.inBackground(pingAt, w, 10_000_000L);
                playPaced(relay, sessions, fronts, peers);
                warmPings.stop();
                players.verifyServed(sessions.size());
            }
            double cpu0 = ProcStat.cpuSeconds(relay.pids());
            var threads0 = ProcStat.cpuSecondsByThread(relay.pids());
            PingProbe.Background probe = PingProbe.inBackground(pingAt, w, 10_000_000L);
            t0 = System.nanoTime();
            playPaced(relay, sessions, fronts, peers);
            elapsed = System.nanoTime() - t0;
            PingProbe.Rtts r = probe.stop();
            rtts = r.sortedMicros();
            pings = r.pings();
            players.verifyServed(sessions.size());
            cpu = ProcStat.cpuSeconds(relay.pids()) - cpu0;
            threads = ProcStat.cpuSecondsByThread(relay.pids());
            threads.replaceAll((k, v) -> v - threads0.getOrDefault(k, 0.0));
            rss = ProcStat.peakRssMb(relay.pids());
        }
        long bytes = sessions.stream().mapToLong(TimedSession::totalBytes).sum();
        long messages = sessionMessages + 2L * pings;
        return new RunResult(bytes / (elapsed / 1e9), rtts, rtts, cpu * 1e6 / messages, relay.unobservedBytes(), rss,
                ProcStat.cpuSpent(threads, cpu, messages));
    }

    /** Every session once at its recorded pace, one robot program each, checking what each received. */
    private static void playPaced(Relay relay, List<TimedSession> sessions, List<InetSocketAddress> fronts,
            ExecutorService peers) throws Exception {
        List<Future<Boolean>> programs = new ArrayList<>();
        for (int s = 0; s < sessions.size(); s++) {
            InetSocketAddress at = fronts.get(s);
            TimedSession session = sessions.get(s);
            programs.add(peers.submit(() -> session.play(new Socket(at.getAddress(), at.getPort()), Direction.CLIENT_TO_SERVER)));
        }
        for (Future<Boolean> p : programs) {
            if (!p.get(300, TimeUnit.SECONDS)) {
                throw new IllegalStateException(relay.name() + ": a paced program received other bytes than recorded");
            }
        }
    }

    private static RunResult runFull(Relay relay, Workload w, int clients, int pings, long loadMessages) throws Exception {
        double cpu;
        double rss;
        Map<String, Double> threads;
        double[] idle;
        double[] busy;
        int busyPings;
        long elapsed;
        try (RecordedPlayers players = new RecordedPlayers(w); relay;
                ExecutorService peers = Executors.newVirtualThreadPerTaskExecutor()) {
            List<InetSocketAddress> fronts = relay.start(players.addresses());
            InetSocketAddress pingAt = fronts.get(fronts.size() - 1);
            for (int pass = 0; pass < 3; pass++) { // so that the JIT has compiled the relay's paths (as paced)
                warmUp(fronts, w, players, peers);
            }
            idle = PingProbe.run(pingAt, w, pings, () -> true).sortedMicros();

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
            PingProbe.Background underLoad = PingProbe.inBackground(pingAt, w, 0);
            double cpu0 = ProcStat.cpuSeconds(relay.pids());
            var threads0 = ProcStat.cpuSecondsByThread(relay.pids());
            long t0 = System.nanoTime();
            go.countDown();
            for (Future<ReplayPeer.Result> p : programs) {
                ReplayPeer.Result r = p.get(300, TimeUnit.SECONDS);
                if (!r.matches()) {
                    throw new IllegalStateException(relay.name() + ": a program received other bytes than recorded, from byte "
                            + r.firstDifference());
                }
            }
            elapsed = System.nanoTime() - t0;
            PingProbe.Rtts b = underLoad.stop();
            busy = b.sortedMicros();
            busyPings = b.pings();
            players.verifyServed(programs.size());
            cpu = ProcStat.cpuSeconds(relay.pids()) - cpu0;
            threads = ProcStat.cpuSecondsByThread(relay.pids());
            threads.replaceAll((k, v) -> v - threads0.getOrDefault(k, 0.0));
            rss = ProcStat.peakRssMb(relay.pids());
        }
        long messages = loadMessages + 2L * busyPings;
        return new RunResult(w.bytes() * clients / (elapsed / 1e9), idle, busy, cpu * 1e6 / messages, relay.unobservedBytes(),
                rss, ProcStat.cpuSpent(threads, cpu, messages));
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

    private static long messages(Workload w) {
        long n = 0;
        for (RecordedConnection c : w.sessions()) {
            for (Direction d : Direction.values()) {
                long[] frames = {0};
                PlayerFramer f = new PlayerFramer(d, e -> frames[0] += e instanceof WireEvent.Frame ? 1 : 0);
                f.accept(c.bytes(d));
                f.end();
                n += frames[0];
            }
        }
        return n;
    }

    private static void report(Phase phase, Map<String, List<RunResult>> results) {
        System.out.println();
        System.out.println("### " + phase.label);
        System.out.println();
        boolean full = phase == Phase.FULL;
        System.out.println("| relay | " + (full ? "throughput MB/s | " : "") + "bytes unobserved | CPU µs/message | "
                + (full ? "added RTT idle p50 / p99 / p99.9 µs | added RTT under load" : "added RTT")
                + " p50 / p99 / p99.9 µs | peak RSS MB |");
        System.out.println("|---|" + (full ? "---|" : "") + "---|---|" + (full ? "---|" : "") + "---|---|");
        double[] baseIdle = null;
        double[] baseBusy = null;
        for (Map.Entry<String, List<RunResult>> e : results.entrySet()) {
            List<RunResult> runs = e.getValue();
            double tput = median(runs.stream().mapToDouble(RunResult::bytesPerSecond).toArray());
            double cpu = median(runs.stream().mapToDouble(RunResult::cpuMicrosPerMessage).toArray());
            double rss = runs.stream().mapToDouble(RunResult::peakRssMb).max().orElse(Double.NaN);
            long unobserved = runs.stream().mapToLong(RunResult::unobserved).max().orElse(-1);
            double[] idle = quantiles(new PingProbe.Rtts(merge(runs, true)));
            double[] busy = quantiles(new PingProbe.Rtts(merge(runs, false)));
            boolean direct = "direct".equals(e.getKey());
            if (direct) {
                baseIdle = idle;
                baseBusy = busy;
            }
            StringBuilder row = new StringBuilder("| " + e.getKey() + " | ");
            if (full) {
                row.append(String.format("%.1f | ", tput / 1e6));
            }
            row.append(unobserved < 0 ? "— (observes nothing)" : unobserved == Long.MAX_VALUE ? "(no report)"
                    : String.format("%,d", unobserved) + (runs.size() > 1 ? " (worst run)" : ""));
            row.append(String.format(" | %s | ", direct ? "—" : String.format("%.2f", cpu)));
            if (full) {
                row.append(added(idle, baseIdle, direct)).append(" | ");
            }
            row.append(added(busy, baseBusy, direct)).append(" | ");
            row.append(Double.isNaN(rss) ? "—" : String.format("%.0f", rss)).append(" |");
            System.out.println(row);
        }
    }

    private static double[] quantiles(PingProbe.Rtts r) {
        return new double[] {r.quantile(0.5), r.quantile(0.99), r.quantile(0.999)};
    }

    private static String added(double[] q, double[] base, boolean direct) {
        if (direct || base == null) {
            return String.format("(direct RTT %.1f / %.1f / %.1f)", q[0], q[1], q[2]);
        }
        return String.format("%+.1f / %+.1f / %+.1f", q[0] - base[0], q[1] - base[1], q[2] - base[2]);
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }

    private static double[] merge(List<RunResult> runs, boolean idle) {
        double[] all = runs.stream().flatMapToDouble(r -> Arrays.stream(idle ? r.idleRtts() : r.loadedRtts())).toArray();
        Arrays.sort(all);
        return all;
    }

    private static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (Exception e) {
            return "?";
        }
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
