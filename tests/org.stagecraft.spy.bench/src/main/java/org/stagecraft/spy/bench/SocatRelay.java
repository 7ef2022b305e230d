package org.stagecraft.spy.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * socat as a plain relay, one process per port forking per connection, with TCP_NODELAY on both
 * sides (without it a Player session through any relay is ~50x slower; see shared notes), and a
 * long half-close allowance: by default socat closes a connection 0.5 s after either side's FIN,
 * which cuts off the other direction of a busy session.
 */
final class SocatRelay implements Relay {
    private final List<Process> processes = new ArrayList<>();

    @Override
    public String name() {
        return "socat";
    }

    @Override
    public List<InetSocketAddress> start(List<InetSocketAddress> upstreams) throws IOException {
        List<InetSocketAddress> fronts = new ArrayList<>();
        for (InetSocketAddress up : upstreams) {
            int port = freePort();
            Process p = new ProcessBuilder("socat", "-t", "120", "TCP-LISTEN:" + port + ",bind=127.0.0.1,reuseaddr,fork,nodelay",
                    "TCP:" + up.getHostString() + ":" + up.getPort() + ",nodelay").redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            processes.add(p);
            InetSocketAddress front = new InetSocketAddress(InetAddress.getLoopbackAddress(), port);
            awaitListening(front, p);
            fronts.add(front);
        }
        return fronts;
    }

    /**
     * socat has no readiness signal, and a probing connection would make it open an upstream
     * session of its own; so look for the listening socket in the kernel's table instead (Linux).
     */
    private static void awaitListening(InetSocketAddress at, Process p) throws IOException {
        String port = String.format(":%04X ", at.getPort());
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (System.nanoTime() < deadline) {
            if (!p.isAlive()) {
                throw new IOException("socat exited with " + p.exitValue() + " (is it installed? apt-get install socat)");
            }
            for (String line : Files.readAllLines(Path.of("/proc/net/tcp"))) {
                String[] f = line.trim().split("\\s+");
                if (f.length > 3 && (f[1] + " ").endsWith(port) && "0A".equals(f[3])) { // 0A = LISTEN
                    return;
                }
            }
            Thread.onSpinWait();
        }
        throw new IOException("socat did not listen on " + at + " within 10 s");
    }

    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    /**
     * socat's processes and their live children: socat forks one per connection, and a child's time
     * reaches its parent's (cutime) only once it has ended and was waited for, so a connection still
     * open at a reading (the ping probe's, for the whole phase) would otherwise not count at all.
     */
    @Override
    public List<Long> pids() {
        List<Long> pids = new java.util.ArrayList<>();
        for (Process p : processes) {
            pids.add(p.pid());
            p.descendants().forEach(d -> pids.add(d.pid()));
        }
        return pids;
    }

    @Override
    public void close() {
        for (Process p : processes) {
            p.descendants().forEach(ProcessHandle::destroy);
            p.destroy();
        }
        processes.clear();
    }
}
