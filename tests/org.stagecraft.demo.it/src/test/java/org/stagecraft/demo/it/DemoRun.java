package org.stagecraft.demo.it;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/** One run of {@code ./stagecraft demo ...} as a user starts it, with what it printed and reported. */
record DemoRun(int exitCode, String output, JsonObject status, double seconds) {

    static Path root() {
        String r = System.getProperty("stagecraft.root");
        Path p = r == null ? Path.of("../..") : Path.of(r);
        if (!Files.isExecutable(p.resolve("stagecraft"))) {
            throw new IllegalStateException("no ./stagecraft script in " + p.toAbsolutePath());
        }
        return p.toAbsolutePath().normalize();
    }

    /**
     * Runs the script and waits for it (at most {@code limitSeconds}, then it is killed and the test
     * fails). The status file is read if the demo wrote one.
     */
    static DemoRun run(Path workspace, Path status, long limitSeconds, String... args) throws IOException, InterruptedException {
        Started started = start(workspace, status, args);
        return started.await(limitSeconds);
    }

    /** The script started, not waited for: {@link Started#await} waits and reads what it left. */
    record Started(Process process, Path out, Path status, long start, String[] args) {
        DemoRun await(long limitSeconds) throws IOException, InterruptedException {
            return DemoRun.await(this, limitSeconds);
        }
    }

    static Started start(Path workspace, Path status, String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of(root().resolve("stagecraft").toString(), "demo"));
        command.addAll(List.of(args));
        if (status != null) {
            command.addAll(List.of("--status", status.toString()));
        }
        Path out = Files.createTempFile(workspace.getParent(), "demo-output", ".txt");
        ProcessBuilder pb = new ProcessBuilder(command).directory(root().toFile()).redirectErrorStream(true)
                .redirectOutput(out.toFile());
        Map<String, String> env = pb.environment();
        env.put("STAGECRAFT_DEMO_WORKSPACE", workspace.toString());
        env.remove("STAGECRAFT_DEMO_EXIT_AFTER");
        env.remove("STAGECRAFT_DEMO_PLAYER");
        long start = System.nanoTime();
        return new Started(pb.start(), out, status, start, args);
    }

    private static DemoRun await(Started started, long limitSeconds) throws IOException, InterruptedException {
        Process p = started.process();
        Path out = started.out();
        Path status = started.status();
        String[] args = started.args();
        long start = started.start();
        if (!p.waitFor(limitSeconds, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            throw new AssertionError("./stagecraft " + String.join(" ", args) + " did not end within " + limitSeconds
                    + " s; output:\n" + Files.readString(out));
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        JsonObject json = status != null && Files.exists(status)
                ? JsonParser.parseString(Files.readString(status)).getAsJsonObject() : null;
        return new DemoRun(p.exitValue(), Files.readString(out), json, seconds);
    }
}
