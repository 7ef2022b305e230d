package org.stagecraft.spy.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The spy in a JVM of its own ({@link SpyServer}), so that, like socat, it does not share a heap
 * and a garbage collector with the load generators that drive it.
 */
final class SpyRelay implements Relay {
    private final Path logDir;
    private final SpyServer.Depth depth;
    private Process process;
    private BufferedReader out;
    private String report = "";

    SpyRelay(Path logDir, SpyServer.Depth depth) {
        this.logDir = logDir;
        this.depth = depth;
    }

    @Override
    public String name() {
        return depth.label;
    }

    @Override
    public List<InetSocketAddress> start(List<InetSocketAddress> upstreams) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(ProcessHandle.current().info().command().orElse("java")));
        // e.g. -Dstagecraft.bench.spyJvm="-Xmx128m -XX:+UseSerialGC" to measure the spy with a bounded heap
        String jvm = System.getProperty("stagecraft.bench.spyJvm", "").trim();
        if (!jvm.isEmpty()) {
            cmd.addAll(List.of(jvm.split("\\s+")));
        }
        cmd.addAll(List.of("--enable-native-access=ALL-UNNAMED", "-cp", ownJar(), SpyServer.class.getName(), depth.name(),
                logDir.toString()));
        for (InetSocketAddress up : upstreams) {
            cmd.add(String.valueOf(up.getPort()));
        }
        process = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        String ready = out.readLine();
        while (ready != null && !ready.startsWith("ready") && ready.startsWith("[")) {
            System.err.println(ready); // the JVM's own lines (e.g. -XX:StartFlightRecording's) come first
            ready = out.readLine();
        }
        if (ready == null || !ready.startsWith("ready")) {
            throw new IOException("the spy process did not start: " + ready);
        }
        List<InetSocketAddress> fronts = new ArrayList<>();
        String[] ports = ready.split(" ");
        for (int i = 1; i < ports.length; i++) {
            fronts.add(new InetSocketAddress(InetAddress.getLoopbackAddress(), Integer.parseInt(ports[i])));
        }
        return fronts;
    }

    @Override
    public String report() {
        return report;
    }

    @Override
    public List<Long> pids() {
        return process == null ? List.of() : List.of(process.pid());
    }

    /** From the spy's own report line: "... N bytes not observed ...". */
    @Override
    public long unobservedBytes() {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(\\d+) bytes not observed").matcher(report);
        return m.find() ? Long.parseLong(m.group(1)) : (depth == SpyServer.Depth.RELAY ? -1 : Long.MAX_VALUE);
    }

    @Override
    public void close() throws IOException {
        if (process == null) {
            return;
        }
        process.getOutputStream().close();
        String line = out.readLine();
        report = line == null ? "(no report)" : line;
        try {
            process.waitFor();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        process = null;
    }

    private static String ownJar() {
        try {
            return Path.of(SpyRelay.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
