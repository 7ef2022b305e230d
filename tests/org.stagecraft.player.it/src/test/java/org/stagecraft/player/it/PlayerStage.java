package org.stagecraft.player.it;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/**
 * The Player/Stage install under test (made by releng/tools/player-stage.sh), its run-time
 * environment as its env.sh sets it, and small process and port helpers for the tests.
 */
final class PlayerStage {
    private static Map<String, String> env;

    private PlayerStage() {
    }

    static Path root() {
        String r = System.getProperty("stagecraft.root");
        return r == null || r.isBlank() ? Path.of("").toAbsolutePath().getParent().getParent() : Path.of(r);
    }

    static Path prefix() {
        String p = System.getProperty("stagecraft.playerStage");
        if (p == null || p.isBlank() || p.startsWith("${")) {
            fail("-Dstagecraft.playerStage=PREFIX is not set: the real-Player tier needs a Player/Stage install "
                    + "(./stagecraft player-stage install --prefix PREFIX)");
        }
        Path prefix = Path.of(p).toAbsolutePath();
        if (!Files.isRegularFile(prefix.resolve("env.sh"))) {
            fail(prefix + "/env.sh does not exist: not a Player/Stage install made by ./stagecraft player-stage install");
        }
        return prefix;
    }

    static Path player() {
        Path p = prefix().resolve("bin/player");
        if (!Files.isExecutable(p)) {
            fail(p + " is not an executable Player");
        }
        return p;
    }

    static Path worlds() {
        return root().resolve("tests/traces/worlds");
    }

    static Path pythonClient() {
        return root().resolve("bundles/org.stagecraft.python/python");
    }

    static Path script(String name) {
        return root().resolve("tests/org.stagecraft.player.it/src/test/resources/org/stagecraft/player/it/" + name);
    }

    /** The Python with the stagecraft_player client's dependencies (pint), checked once. */
    static String python() {
        String py = System.getProperty("stagecraft.python", "python3");
        if (py.isBlank() || py.startsWith("${")) {
            py = "python3";
        }
        return py;
    }

    /** The variables env.sh exports (PATH, LD_LIBRARY_PATH, PLAYERPATH, STAGEPATH, PYTHONPATH...), read by sourcing it. */
    static synchronized Map<String, String> env() {
        if (env == null) {
            Path sh = prefix().resolve("env.sh");
            ProcessBuilder pb = new ProcessBuilder("bash", "-c", ". \"$1\" && env -0", "env", sh.toString());
            pb.environment().clear();
            pb.environment().put("PATH", "/usr/local/bin:/usr/bin:/bin");
            try {
                Process p = pb.redirectErrorStream(true).start();
                String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
                if (!p.waitFor(30, TimeUnit.SECONDS) || p.exitValue() != 0) {
                    fail("sourcing " + sh + " failed: " + out);
                }
                Map<String, String> m = new HashMap<>();
                for (String kv : out.split("\0")) {
                    int eq = kv.indexOf('=');
                    if (eq > 0) {
                        m.put(kv.substring(0, eq), kv.substring(eq + 1));
                    }
                }
                Map<String, String> keep = new HashMap<>();
                for (String k : List.of("PATH", "LD_LIBRARY_PATH", "PLAYERPATH", "STAGEPATH", "PYTHONPATH",
                        "STAGECRAFT_PLAYERC_PYTHON")) {
                    if (m.containsKey(k)) {
                        keep.put(k, m.get(k));
                    }
                }
                // the test JVM's own PATH after env.sh's (python3, bash ...)
                keep.put("PATH", keep.get("PATH") + ":" + System.getenv().getOrDefault("PATH", "/usr/bin:/bin"));
                env = Map.copyOf(keep);
            } catch (IOException | InterruptedException e) {
                throw new AssertionError("cannot source " + sh + ": " + e, e);
            }
        }
        return env;
    }

    /**
     * {@code n} ports free on every address and on loopback. Player binds 0.0.0.0 (it has no option
     * for an address), so a port is only usable if nothing listens on it on any address.
     */
    static List<Integer> freePorts(int n) throws IOException {
        List<Integer> out = new ArrayList<>();
        for (int tries = 0; out.size() < n && tries < 200; tries++) {
            int port;
            try (ServerSocket s = new ServerSocket()) {
                s.setReuseAddress(false);
                s.bind(new InetSocketAddress(InetAddress.getByName("0.0.0.0"), 0));
                port = s.getLocalPort();
            }
            if (!out.contains(port) && isFree(port)) {
                out.add(port);
            }
        }
        if (out.size() < n) {
            fail("could not find " + n + " free ports");
        }
        return out;
    }

    /** Nothing listens on {@code port}, neither on all addresses nor on loopback. */
    static boolean isFree(int port) {
        for (String host : List.of("0.0.0.0", "127.0.0.1")) {
            try (ServerSocket s = new ServerSocket()) {
                s.setReuseAddress(true);
                s.bind(new InetSocketAddress(InetAddress.getByName(host), port));
            } catch (IOException e) {
                return false;
            }
        }
        return true;
    }

    /** An X display number no X server uses (no socket, no lock file), for a private Xvfb. */
    static int freeDisplay() {
        for (int n = 100 + (int) (ProcessHandle.current().pid() % 300); n < 1000; n++) {
            if (!Files.exists(Path.of("/tmp/.X11-unix/X" + n)) && !Files.exists(Path.of("/tmp/.X" + n + "-lock"))) {
                return n;
            }
        }
        throw new AssertionError("no free X display number");
    }

    /** Polls until {@code condition} holds or {@code within} passes. */
    /** A private Xvfb on {@code display} as a session's user tool, ready when it prints its display number. */
    static org.stagecraft.tools.process.ToolSpec xvfb(int display) {
        return org.stagecraft.tools.process.ToolSpec.of("Xvfb", List.of("Xvfb", ":" + display, "-screen", "0", "640x480x24",
                "-nolisten", "tcp", "-displayfd", "1")).withReadiness(
                        org.stagecraft.tools.process.Readiness.line("^" + display + "$"), Duration.ofSeconds(30));
    }

    static boolean await(Duration within, java.util.function.BooleanSupplier condition) throws InterruptedException {
        long end = System.nanoTime() + within.toNanos();
        while (System.nanoTime() < end) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(50);
        }
        return condition.getAsBoolean();
    }

    /** A program the test started, its output collected line by line; {@link #close()} ends its whole tree. */
    static final class Program implements AutoCloseable {
        final String name;
        final Process process;
        final List<String> lines = new CopyOnWriteArrayList<>();
        private final Thread reader;

        Program(String name, List<String> command, Map<String, String> extraEnv, Path dir) throws IOException {
            this.name = name;
            ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
            if (dir != null) {
                pb.directory(dir.toFile());
            }
            pb.environment().putAll(extraEnv);
            process = pb.start();
            reader = Thread.ofVirtual().start(() -> {
                try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                    String l;
                    while ((l = r.readLine()) != null) {
                        lines.add(l);
                    }
                } catch (IOException e) {
                    lines.add("[test] reading output failed: " + e);
                }
            });
        }

        boolean anyLine(Predicate<String> p) {
            return lines.stream().anyMatch(p);
        }

        long count(Predicate<String> p) {
            return lines.stream().filter(p).count();
        }

        /** Waits for the program to end by itself; fails (naming it and its output) if it does not in time. */
        int awaitExit(Duration within) throws InterruptedException {
            if (!process.waitFor(within.toMillis(), TimeUnit.MILLISECONDS)) {
                fail(name + " did not end within " + within + "; its output:\n" + output());
            }
            reader.join(Duration.ofSeconds(10));
            return process.exitValue();
        }

        String output() {
            List<String> l = List.copyOf(lines);
            return String.join("\n", l.subList(Math.max(0, l.size() - 40), l.size()));
        }

        @Override
        public void close() throws InterruptedException {
            List<ProcessHandle> tree = new ArrayList<>(process.descendants().toList());
            tree.add(process.toHandle());
            for (ProcessHandle h : tree) {
                h.destroy();
            }
            long end = System.nanoTime() + Duration.ofSeconds(5).toNanos();
            for (ProcessHandle h : tree) {
                while (h.isAlive() && System.nanoTime() < end) {
                    Thread.sleep(20);
                }
                if (h.isAlive()) {
                    h.destroyForcibly();
                }
            }
            process.waitFor(5, TimeUnit.SECONDS);
            reader.join(Duration.ofSeconds(5));
        }
    }
}
