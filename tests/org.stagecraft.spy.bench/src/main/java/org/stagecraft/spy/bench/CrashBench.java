package org.stagecraft.spy.bench;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * The crash window of the spy log (issue 25, item 5), against the real command ({@code ./stagecraft
 * spy --log}, with the script's own JVM flags): recorded robot programs talk to recorded Players
 * through the spy, which is killed with SIGKILL at a random moment; then the log is read as a user
 * would after the crash (recovery: every complete chunk) and compared with what the peers actually
 * received, stream by stream.
 *
 * <p>Two modes: <b>paced</b>, six robots' recorded sessions replayed at their recorded times (both
 * sides), and <b>full</b>, six recorded sessions (lengthened) replayed as fast as the sockets take them.
 * The kill moments are random, one in each of {@code --rounds} equal slices of the kill range (so
 * the first second is always among them). For every round it prints: wire messages relayed (what the
 * peers received, framed as the spy frames it: banners, Player messages) and in the log; whether
 * every logged stream is an exact byte prefix of what was relayed; the time from the last logged
 * message's capture to the kill; and the unlogged span: from the arrival of the first relayed byte
 * that is not in the log to the kill (0 when everything relayed is in the log).
 *
 * <pre>./stagecraft bench crash [--mode both|paced|full] [--rounds 10] [--seed 25] [--paced-until 10]
 *     [--full-until 3] [--repeat 400]</pre>
 * {@code -Dstagecraft.root=DIR} runs the {@code stagecraft} script of another checkout (e.g. an older
 * commit built in a worktree), for before/after figures.
 */
public final class CrashBench {
    private CrashBench() {
    }

    /** One direction of a session as sent: chunks and when (seconds after the start; all 0 at full speed). */
    private record Side(List<Double> times, List<byte[]> chunks) {
        long length() {
            long n = 0;
            for (byte[] c : chunks) {
                n += c.length;
            }
            return n;
        }
    }

    private record Session(Side client, Side server) {
    }

    /** What one peer received on one stream: how much, when, and whether it was what the other side sent. */
    private static final class Received {
        final Side expected;
        long count;
        boolean matches = true;
        long[] at = new long[1024]; // cumulative count after each read
        long[] when = new long[1024]; // its arrival, epoch nanoseconds
        int samples;
        private int chunk;
        private int inChunk;

        Received(Side expected) {
            this.expected = expected;
        }

        void got(byte[] buf, int n, long epochNanos) {
            for (int i = 0; i < n && matches; i++) {
                while (chunk < expected.chunks().size() && inChunk >= expected.chunks().get(chunk).length) {
                    chunk++;
                    inChunk = 0;
                }
                if (chunk >= expected.chunks().size() || expected.chunks().get(chunk)[inChunk++] != buf[i]) {
                    matches = false;
                }
            }
            count += n;
            if (samples == at.length) {
                at = Arrays.copyOf(at, samples * 2);
                when = Arrays.copyOf(when, samples * 2);
            }
            at[samples] = count;
            when[samples] = epochNanos;
            samples++;
        }

        /** When the byte at {@code offset} arrived. */
        long arrivalOf(long offset) {
            for (int i = 0; i < samples; i++) {
                if (at[i] > offset) {
                    return when[i];
                }
            }
            return Long.MAX_VALUE;
        }
    }

    private record Round(int relayed, long logged, boolean prefixes, String problem, double lastLoggedGapMs,
            double unloggedSpanMs, double killAt) {
    }

    public static void main(String[] args) throws Exception {
        Map<String, String> opt = new HashMap<>(Map.of("mode", "both", "rounds", "10", "seed", "25", "paced-until", "10",
                "full-until", "3", "repeat", "400"));
        for (int i = 0; i + 1 < args.length; i += 2) {
            if (!args[i].startsWith("--") || !opt.containsKey(args[i].substring(2))) {
                throw new IllegalArgumentException("unknown option " + args[i] + " (known: " + opt.keySet() + ")");
            }
            opt.put(args[i].substring(2), args[i + 1]);
        }
        Path root = Path.of(System.getProperty("stagecraft.root", ".")).toAbsolutePath();
        int rounds = Integer.parseInt(opt.get("rounds"));
        Random random = new Random(Long.parseLong(opt.get("seed")));
        String mode = opt.get("mode");
        System.out.printf("stagecraft spy of %s (%s), killed with SIGKILL %d times per mode%n", root,
                git(root), rounds);
        if (!mode.equals("full")) {
            List<Session> paced = new ArrayList<>();
            for (TimedSession t : TimedSession.load(6, 15)) {
                paced.add(new Session(new Side(t.clientTimes(), t.clientChunks()), new Side(t.serverTimes(), t.serverChunks())));
            }
            run("recorded pace, six robots", root, paced, rounds, Double.parseDouble(opt.get("paced-until")), random);
        }
        if (!mode.equals("paced")) {
            List<Session> full = new ArrayList<>();
            for (RecordedConnection c : Workload.load(6, Integer.parseInt(opt.get("repeat"))).sessions()) {
                full.add(new Session(new Side(Collections.nCopies(c.clientChunks().size(), 0.0), c.clientChunks()),
                        new Side(Collections.nCopies(c.serverChunks().size(), 0.0), c.serverChunks())));
            }
            run("full speed, six sessions", root, full, rounds, Double.parseDouble(opt.get("full-until")), random);
        }
    }

    private static void run(String label, Path root, List<Session> sessions, int rounds, double until, Random random)
            throws Exception {
        long total = 0;
        for (Session s : sessions) {
            total += s.client().length() + s.server().length();
        }
        System.out.printf("%n%s: %d sessions, %.1f MB in all; kills between 0.05 and %.1f s after the programs start%n",
                label, sessions.size(), total / 1e6, until);
        List<Round> done = new ArrayList<>();
        for (int i = 0; i < rounds; i++) {
            double killAt = 0.05 + (i + random.nextDouble()) * (until - 0.05) / rounds;
            Round r = round(root, sessions, killAt);
            done.add(r);
            System.out.printf(Locale.ROOT,
                    "  kill at %5.2f s: %7d messages relayed, %7d in the log (%5.1f %%), prefixes %s, last logged %7.1f ms"
                            + " before the kill, unlogged span %7.1f ms%s%n",
                    killAt, r.relayed(), r.logged(), r.relayed() == 0 ? 100.0 : 100.0 * r.logged() / r.relayed(),
                    r.prefixes() ? "exact" : "WRONG", r.lastLoggedGapMs(), r.unloggedSpanMs(),
                    r.problem().isEmpty() ? "" : " (" + r.problem() + ")");
        }
        long relayed = done.stream().mapToLong(Round::relayed).sum();
        long logged = done.stream().mapToLong(Round::logged).sum();
        System.out.printf(Locale.ROOT, "%s: %d of %d relayed messages in the logs (%.2f %%), %d not; every stream an exact"
                + " prefix: %s%n", label, logged, relayed, 100.0 * logged / Math.max(1, relayed), relayed - logged,
                done.stream().allMatch(Round::prefixes));
        System.out.printf(Locale.ROOT, "  messages lost per kill: %s%n", spread(done.stream().mapToDouble(r -> r.relayed() - r.logged())
                .toArray(), "%.0f"));
        System.out.printf(Locale.ROOT, "  last logged message before the kill (ms): %s%n",
                spread(done.stream().mapToDouble(Round::lastLoggedGapMs).toArray(), "%.1f"));
        System.out.printf(Locale.ROOT, "  unlogged span before the kill (ms): %s%n",
                spread(done.stream().mapToDouble(Round::unloggedSpanMs).toArray(), "%.1f"));
    }

    private static String spread(double[] v, String f) {
        double[] s = v.clone();
        Arrays.sort(s);
        double median = s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
        return String.format(Locale.ROOT, "min " + f + ", median " + f + ", max " + f, s[0], median, s[s.length - 1]);
    }

    private static Round round(Path root, List<Session> sessions, double killAt) throws Exception {
        Path dir = Files.createTempDirectory("stagecraft-crash");
        Path log = dir.resolve("crash.mcap");
        List<AutoCloseable> open = new ArrayList<>();
        List<Thread> peers = new ArrayList<>();
        Received[] toPlayer = new Received[sessions.size()];
        Received[] toProgram = new Received[sessions.size()];
        List<String> cmd = new ArrayList<>(List.of(root.resolve("stagecraft").toString(), "spy"));
        for (int i = 0; i < sessions.size(); i++) {
            Session s = sessions.get(i);
            toPlayer[i] = new Received(s.client());
            toProgram[i] = new Received(s.server());
            ServerSocket player = new ServerSocket(0, 10, InetAddress.getLoopbackAddress());
            open.add(player);
            Received got = toPlayer[i];
            peers.add(Thread.ofPlatform().daemon().start(() -> {
                try (Socket c = player.accept()) {
                    talk(c, s.server(), got);
                } catch (IOException e) {
                    // the spy was killed
                }
            }));
            cmd.addAll(List.of("--listen", "127.0.0.1:0", "--to", "127.0.0.1:" + player.getLocalPort()));
        }
        cmd.addAll(List.of("--log", log.toString()));
        Process spy = new ProcessBuilder(cmd).directory(root.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        ByteArrayOutputStream said = new ByteArrayOutputStream();
        Thread.ofPlatform().daemon().start(() -> {
            try (InputStream in = spy.getErrorStream()) {
                byte[] buf = new byte[8192];
                for (int n = in.read(buf); n >= 0; n = in.read(buf)) {
                    synchronized (said) {
                        said.write(buf, 0, n);
                    }
                }
            } catch (IOException ignored) {
                // the spy ended
            }
        });
        List<Integer> fronts = new ArrayList<>();
        Pattern spying = Pattern.compile("(?m)^spying [\\d.]+:(\\d+) -> ");
        long started = System.nanoTime();
        while (fronts.size() < sessions.size()) {
            String text;
            synchronized (said) {
                text = said.toString(StandardCharsets.UTF_8);
            }
            if (!spy.isAlive() || System.nanoTime() - started > TimeUnit.SECONDS.toNanos(120)) {
                throw new IllegalStateException("stagecraft spy did not start listening: " + text);
            }
            fronts.clear();
            Matcher m = spying.matcher(text);
            while (m.find()) {
                fronts.add(Integer.parseInt(m.group(1)));
            }
            LockSupport.parkNanos(10_000_000); // polls what the command said
        }
        long start = System.nanoTime();
        for (int i = 0; i < sessions.size(); i++) {
            Socket c = new Socket(InetAddress.getLoopbackAddress(), fronts.get(i));
            open.add(c);
            Session s = sessions.get(i);
            Received got = toProgram[i];
            peers.add(Thread.ofPlatform().daemon().start(() -> {
                try (c) {
                    talk(c, s.client(), got);
                } catch (IOException e) {
                    // the spy was killed
                }
            }));
        }
        long due = start + (long) (killAt * 1e9);
        for (long wait = due - System.nanoTime(); wait > 0; wait = due - System.nanoTime()) {
            LockSupport.parkNanos(wait);
        }
        long killEpoch = epochNanos();
        spy.destroyForcibly(); // SIGKILL
        if (!spy.waitFor(30, TimeUnit.SECONDS)) {
            throw new IllegalStateException("the spy did not die");
        }
        for (Thread t : peers) {
            t.join(TimeUnit.SECONDS.toMillis(30));
        }
        for (AutoCloseable c : open) {
            c.close();
        }

        // what was relayed: what the peers received, checked against what the other side sent
        StringBuilder problem = new StringBuilder();
        int relayed = 0;
        for (int i = 0; i < sessions.size(); i++) {
            relayed += events(toPlayer[i], Direction.CLIENT_TO_SERVER) + events(toProgram[i], Direction.SERVER_TO_CLIENT);
            if (!toPlayer[i].matches || !toProgram[i].matches) {
                problem.append("session ").append(i).append(" relayed other bytes than sent; ");
            }
        }
        long logged = 0;
        boolean prefixes = true;
        long lastCapture = Long.MIN_VALUE;
        long firstUnlogged = Long.MAX_VALUE;
        long[][] logLength = new long[sessions.size()][2];
        try (SpyLogReader r = SpyLogReader.open(log)) {
            for (Iterator<LogEntry> it = r.entries(); it.hasNext();) {
                if (it.next() instanceof LogEntry.Wire w) {
                    logged++;
                    lastCapture = Math.max(lastCapture, w.captureNanos());
                }
            }
            for (LogConnection c : r.connections()) {
                int i = fronts.indexOf(Integer.parseInt(c.listen().substring(c.listen().lastIndexOf(':') + 1)));
                if (i < 0) {
                    problem.append("a connection the bench did not make: ").append(c.listen()).append("; ");
                    prefixes = false;
                    continue;
                }
                for (Direction d : Direction.values()) {
                    Received got = d == Direction.CLIENT_TO_SERVER ? toPlayer[i] : toProgram[i];
                    byte[] inLog;
                    try {
                        inLog = r.streamBytes(c.conn(), d);
                    } catch (IOException e) {
                        problem.append("stream ").append(c.conn()).append(' ').append(d).append(": ").append(e.getMessage());
                        prefixes = false;
                        continue;
                    }
                    logLength[i][d.ordinal()] = inLog.length;
                    if (inLog.length > got.count || !isPrefix(inLog, got.expected)) {
                        problem.append("stream ").append(c.conn()).append(' ').append(d).append(" is not a prefix of what was relayed; ");
                        prefixes = false;
                    }
                }
            }
        } catch (IOException e) {
            problem.append("log not readable (").append(e.getMessage()).append("); ");
        }
        for (int i = 0; i < sessions.size(); i++) {
            for (Direction d : Direction.values()) {
                Received got = d == Direction.CLIENT_TO_SERVER ? toPlayer[i] : toProgram[i];
                if (logLength[i][d.ordinal()] < got.count) {
                    firstUnlogged = Math.min(firstUnlogged, got.arrivalOf(logLength[i][d.ordinal()]));
                }
            }
        }
        Files.deleteIfExists(log);
        Files.deleteIfExists(dir);
        double lastGap = lastCapture == Long.MIN_VALUE ? killAt * 1e3 : (killEpoch - lastCapture) / 1e6;
        double span = firstUnlogged == Long.MAX_VALUE ? 0 : Math.max(0, (killEpoch - firstUnlogged) / 1e6);
        return new Round(relayed, logged, prefixes, problem.toString(), lastGap, span, killAt);
    }

    /** Sends one side as scheduled on a thread of its own and reads the other side until the end. */
    private static void talk(Socket s, Side send, Received got) throws IOException {
        s.setTcpNoDelay(true);
        OutputStream out = s.getOutputStream();
        Thread sender = Thread.ofPlatform().daemon().start(() -> {
            long start = System.nanoTime();
            try {
                for (int i = 0; i < send.chunks().size(); i++) {
                    long due = start + (long) (send.times().get(i) * 1e9);
                    for (long wait = due - System.nanoTime(); wait > 0; wait = due - System.nanoTime()) {
                        LockSupport.parkNanos(wait); // the recorded pace
                    }
                    out.write(send.chunks().get(i));
                }
                s.shutdownOutput();
            } catch (IOException e) {
                // the spy was killed
            }
        });
        InputStream in = s.getInputStream();
        byte[] buf = new byte[65536];
        try {
            for (int n = in.read(buf); n >= 0; n = in.read(buf)) {
                got.got(buf, n, epochNanos());
            }
        } catch (IOException e) {
            // reset: the spy was killed
        }
        try {
            sender.join(TimeUnit.SECONDS.toMillis(30));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static long epochNanos() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000_000L + now.getNano();
    }

    /** Wire events (banner, complete Player messages) in what a peer received, as the spy frames them. */
    private static int events(Received r, Direction dir) {
        int[] n = {0};
        PlayerFramer f = new PlayerFramer(dir, e -> n[0]++);
        long left = r.count;
        for (byte[] c : r.expected.chunks()) {
            if (left <= 0) {
                break;
            }
            int take = (int) Math.min(left, c.length);
            f.accept(c, 0, take);
            left -= take;
        }
        return n[0];
    }

    private static boolean isPrefix(byte[] b, Side sent) {
        int at = 0;
        for (byte[] c : sent.chunks()) {
            if (at >= b.length) {
                return true;
            }
            int n = Math.min(c.length, b.length - at);
            if (!Arrays.equals(b, at, at + n, c, 0, n)) {
                return false;
            }
            at += n;
        }
        return at >= b.length;
    }

    private static String git(Path root) {
        try {
            Process p = new ProcessBuilder("git", "-C", root.toString(), "log", "--oneline", "-1").redirectErrorStream(true)
                    .start();
            String s = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            p.waitFor();
            return s;
        } catch (IOException | InterruptedException e) {
            return "?";
        }
    }
}
