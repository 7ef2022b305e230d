package org.stagecraft.tools.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An IDE that dies hard takes its tools with it: a child JVM ({@link DyingIde}) starts a tool through
 * {@link SupervisedTool}, is killed with SIGKILL (no shutdown hook runs), and the tool, its children
 * and the reaper itself must be gone soon after.
 */
@Timeout(value = 90, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class OrphanReaperTest {
    private static final Duration START = Duration.ofSeconds(30);
    /** The reaper's grace between SIGTERM and SIGKILL is 3 s; the rest is slack for a busy machine. */
    private static final Duration GONE = Duration.ofSeconds(20);

    private final List<Long> leftovers = new ArrayList<>();
    private Process ide;

    @AfterEach
    void cleanUp() {
        if (ide != null) {
            ide.destroyForcibly();
        }
        // never leave a process behind, even when the test failed
        leftovers.forEach(pid -> ProcessHandle.of(pid).ifPresent(ProcessHandle::destroyForcibly));
    }

    @Test
    void aToolOnATerminalThatIgnoresHangUpDiesWithItsIde() throws Exception {
        killedIdeLeavesNothing(true, "trap '' HUP; sleep 600 & echo READY; wait");
    }

    @Test
    void aToolOnPipesThatIgnoresTermAndHangUpDiesWithItsIde() throws Exception {
        // ignored signals stay ignored in the child: only the SIGKILL after the grace ends them
        killedIdeLeavesNothing(false, "trap '' HUP TERM; sleep 600 & echo READY; wait");
    }

    @Test
    void aToolThatEndedIsNoLongerRegistered() throws Exception {
        OrphanReaper reaper = new OrphanReaper();
        Process p = new ProcessBuilder("true").start();
        assertEquals(null, reaper.register(p.pid()), "the reaper starts");
        assertEquals(0, p.waitFor());
        reaper.unregister(p.pid());
        ProcessHandle script = reaper.process();
        assertNotNull(script);
        assertTrue(script.isAlive(), "the reaper waits for end-of-file while this JVM lives");
    }

    private void killedIdeLeavesNothing(boolean terminal, String script) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        ide = new ProcessBuilder(java, "--enable-native-access=ALL-UNNAMED", "-Dstagecraft.tools.pty=" + terminal,
                "-cp", System.getProperty("java.class.path"), DyingIde.class.getName(), script)
                .redirectErrorStream(true).start();
        BlockingQueue<String> lines = new LinkedBlockingQueue<>();
        Thread.ofPlatform().daemon().start(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(ide.getInputStream(), StandardCharsets.UTF_8))) {
                for (String l = r.readLine(); l != null; l = r.readLine()) {
                    lines.add(l);
                }
            } catch (Exception e) {
                // the JVM was killed
            }
        });
        List<Long> tree = pids(awaitLine(lines, "TREE "));
        leftovers.addAll(tree);
        String reaper = awaitLine(lines, "REAPER ");
        assertEquals(2, tree.size(), "the shell and its sleep: " + tree);
        for (long pid : tree) {
            assertTrue(alive(pid), "pid " + pid + " runs before the IDE dies");
        }

        ide.destroyForcibly();
        assertTrue(ide.waitFor(10, TimeUnit.SECONDS), "the IDE's JVM ends on SIGKILL");

        long deadline = System.nanoTime() + GONE.toNanos();
        List<Long> running = tree;
        while (!running.isEmpty() && System.nanoTime() < deadline) {
            running = tree.stream().filter(OrphanReaperTest::alive).toList();
            if (!running.isEmpty()) {
                ProcessHandle.of(running.get(0)).ifPresent(h -> {
                    try {
                        h.onExit().get(100, TimeUnit.MILLISECONDS);
                    } catch (Exception e) {
                        // still running: poll again
                    }
                });
            }
        }
        assertTrue(running.isEmpty(), "still running " + GONE.toSeconds() + " s after the IDE was killed: " + running);
        assertNotEquals("none", reaper, "a reaper was started");
        awaitGone(Long.parseLong(reaper), "the reaper ends once its work is done");
    }

    private static boolean alive(long pid) {
        return ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false);
    }

    private static void awaitGone(long pid, String what) throws Exception {
        var h = ProcessHandle.of(pid);
        if (h.isPresent()) {
            try {
                h.get().onExit().get(GONE.toSeconds(), TimeUnit.SECONDS);
            } catch (java.util.concurrent.TimeoutException e) {
                fail(what + ": pid " + pid + " still runs");
            }
        }
        assertTrue(!alive(pid), what);
    }

    private String awaitLine(BlockingQueue<String> lines, String prefix) throws Exception {
        long deadline = System.nanoTime() + START.toNanos();
        List<String> seen = new ArrayList<>();
        while (System.nanoTime() < deadline) {
            String l = lines.poll(100, TimeUnit.MILLISECONDS);
            if (l != null) {
                if (l.startsWith(prefix)) {
                    return l.substring(prefix.length());
                }
                seen.add(l);
            } else if (!ide.isAlive() && lines.isEmpty()) {
                break;
            }
        }
        fail("the stand-in IDE printed no '" + prefix.trim() + "' line; its output:\n" + String.join("\n", seen));
        return null;
    }

    private static List<Long> pids(String text) {
        return Arrays.stream(text.trim().split("\\s+")).map(Long::parseLong).toList();
    }
}
