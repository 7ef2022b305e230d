package org.stagecraft.spy.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.xdr.XdrWriter;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.recording.peers.ReplayPeer;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.spy.log.LogConnection;
import org.stagecraft.spy.log.SpyLogReader;

/**
 * The hostile-client scenario of issue 17, against the real command ({@code ./stagecraft spy --log},
 * with the heap the script gives it): {@code --clients} connections each announce an 8 MiB Player
 * message, send {@code --stall-mb} of it and stall, holding their connections; then a well-behaved
 * robot program replays a recorded session. Passes when the spy is still alive, the program's
 * session went through byte-exact both ways, and the log holds that session completely; prints the
 * spy's peak resident memory and what it counted as unobserved.
 *
 * <pre>./stagecraft bench hostile [--clients 100] [--stall-mb 4]</pre>
 */
public final class HostileClientsBench {
    private HostileClientsBench() {
    }

    public static void main(String[] args) throws Exception {
        int clients = 100;
        int stallMb = 4;
        for (int i = 0; i + 1 < args.length; i += 2) {
            switch (args[i]) {
                case "--clients" -> clients = Integer.parseInt(args[i + 1]);
                case "--stall-mb" -> stallMb = Integer.parseInt(args[i + 1]);
                default -> throw new IllegalArgumentException("unknown option " + args[i] + " (known: --clients, --stall-mb)");
            }
        }
        Path root = Path.of(System.getProperty("stagecraft.root", "."));
        RecordedConnection session = RecordedConnection.read(TraceCorpus.file("pioneer-laser-sonar.gt.trace.jsonl")).get(0);
        Path dir = Files.createTempDirectory("stagecraft-hostile");
        Path log = dir.resolve("hostile.mcap");

        AtomicLong sunk = new AtomicLong();
        ServerSocket sink = new ServerSocket(0, 1000, InetAddress.getLoopbackAddress());
        Thread.ofVirtual().start(() -> RecordedPlayers.acceptLoop(sink, s -> {
            try (s; InputStream in = s.getInputStream()) {
                byte[] buf = new byte[65536];
                for (int n = in.read(buf); n >= 0; n = in.read(buf)) {
                    sunk.addAndGet(n);
                }
            } catch (IOException ignored) {
                // reset by the spy at the end
            }
        }));
        ServerSocket player = new ServerSocket(0, 10, InetAddress.getLoopbackAddress());
        CompletableFuture<ReplayPeer.Result> served = new CompletableFuture<>();
        Thread.ofVirtual().start(() -> {
            try (Socket s = player.accept()) {
                served.complete(ReplayPeer.serve(s, session));
            } catch (IOException e) {
                served.completeExceptionally(e);
            }
        });

        Process spy = new ProcessBuilder(root.resolve("stagecraft").toString(), "spy",
                "--listen", "127.0.0.1:0", "--to", "127.0.0.1:" + sink.getLocalPort(),
                "--listen", "127.0.0.1:0", "--to", "127.0.0.1:" + player.getLocalPort(), "--log", log.toString())
                .directory(root.toFile()).redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")))
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        // everything the command says on stderr, read raw from the start by a thread of its own
        java.io.ByteArrayOutputStream rest = new java.io.ByteArrayOutputStream();
        Thread drain = Thread.ofPlatform().daemon().start(() -> {
            try (InputStream in = spy.getErrorStream()) {
                byte[] buf = new byte[8192];
                for (int n = in.read(buf); n >= 0; n = in.read(buf)) {
                    synchronized (rest) {
                        rest.write(buf, 0, n);
                    }
                }
            } catch (IOException ignored) {
                // the spy ended
            }
        });
        List<Integer> fronts = new ArrayList<>();
        Pattern spying = Pattern.compile("(?m)^spying [\\d.]+:(\\d+) -> ");
        long started = System.nanoTime();
        while (fronts.size() < 2) {
            if (!spy.isAlive() || System.nanoTime() - started > TimeUnit.SECONDS.toNanos(120)) {
                throw new IllegalStateException("stagecraft spy did not start listening: " + text(rest));
            }
            fronts.clear();
            Matcher m = spying.matcher(text(rest));
            while (m.find()) {
                fronts.add(Integer.parseInt(m.group(1)));
            }
            java.util.concurrent.locks.LockSupport.parkNanos(10_000_000); // polls what the command said
        }
        System.out.printf("stagecraft spy (pid %d, the script's default heap) relays to a sink and to a recorded Player%n",
                spy.pid());

        long t0 = System.nanoTime();
        XdrWriter w = new XdrWriter(MessageHeader.SIZE);
        new MessageHeader(0, 0, 6, 0, 1, 1, 1.0, 0, MessageHeader.MAX_PAYLOAD).write(w);
        byte[] announce = w.toByteArray();
        byte[] part = new byte[stallMb << 20];
        new Random(17).nextBytes(part);
        List<Socket> attackers = new ArrayList<>();
        for (int i = 0; i < clients; i++) {
            Socket s = new Socket(InetAddress.getLoopbackAddress(), fronts.get(0));
            OutputStream out = s.getOutputStream();
            out.write(announce);
            out.write(part); // then stall, holding the connection
            attackers.add(s);
        }
        long attack = (long) clients * (announce.length + part.length);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(300);
        while (sunk.get() < attack && System.nanoTime() < deadline) {
            java.util.concurrent.locks.LockSupport.parkNanos(10_000_000); // polls the sink's count
        }
        System.out.printf("%d clients announced 8 MiB messages, sent %d MiB of each and stalled: %.0f MB relayed in %.1f s%n",
                clients, stallMb, sunk.get() / 1e6, (System.nanoTime() - t0) / 1e9);
        double rssAttack = rssMb(spy.pid(), "VmRSS:");

        ReplayPeer.Result program = ReplayPeer.client(new Socket(InetAddress.getLoopbackAddress(), fronts.get(1)), session);
        ReplayPeer.Result playerSide = served.get(60, TimeUnit.SECONDS);
        boolean alive = spy.isAlive();
        double peak = rssMb(spy.pid(), "VmHWM:");
        for (Socket s : attackers) {
            s.close();
        }
        spy.destroy(); // SIGTERM: the command closes the log and exits
        boolean ended = spy.waitFor(60, TimeUnit.SECONDS);
        int status = ended ? spy.exitValue() : -1;
        boolean logged;
        long givenUp = 0;
        long notObserved = 0;
        try (SpyLogReader r = SpyLogReader.open(log)) {
            for (var it = r.entries(); it.hasNext();) {
                if (it.next() instanceof org.stagecraft.spy.log.LogEntry.Diagnostic d) {
                    boolean gaveUp = d.text().contains("was given up");
                    givenUp += gaveUp ? 1 : 0;
                    notObserved += !gaveUp && d.text().contains("not observed") ? 1 : 0;
                }
            }
            LogConnection good = r.connections().stream().filter(c -> c.listen().endsWith(":" + fronts.get(1))).findFirst()
                    .orElseThrow();
            logged = Arrays.equals(session.clientBytes(), r.streamBytes(good.conn(), Direction.CLIENT_TO_SERVER))
                    && Arrays.equals(session.serverBytes(), r.streamBytes(good.conn(), Direction.SERVER_TO_CLIENT));
        }
        System.out.printf("spy alive during the attack: %s; resident memory after the attack %.0f MB, peak %.0f MB%n", alive,
                rssAttack, peak);
        System.out.printf("well-behaved program byte-exact both ways: %s; its session complete in the log: %s%n",
                program.matches() && playerSide.matches(), logged);
        System.out.printf("exit status %d; the log records %d messages given up to bound memory and %d other gaps%n", status,
                givenUp, notObserved);
        String said = text(rest);
        said.lines().filter(l -> l.contains("observation failed")).limit(3).forEach(l -> System.out.println("  " + l));
        Files.deleteIfExists(log);
        Files.deleteIfExists(dir);
        boolean pass = alive && program.matches() && playerSide.matches() && logged && status == 0;
        System.out.println(pass ? "PASS" : "FAIL");
        System.exit(pass ? 0 : 1);
    }

    private static String text(java.io.ByteArrayOutputStream b) {
        synchronized (b) {
            return b.toString(StandardCharsets.UTF_8);
        }
    }

    private static double rssMb(long pid, String field) throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/" + pid + "/status"))) {
            if (line.startsWith(field)) {
                return Long.parseLong(line.replaceAll("\\D", "")) / 1024.0;
            }
        }
        return Double.NaN;
    }
}
