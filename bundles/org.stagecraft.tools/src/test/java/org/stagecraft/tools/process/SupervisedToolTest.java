package org.stagecraft.tools.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.tools.session.Ports;

/** Supervision of real processes: readiness, exits, restarts, whole-tree stops, clear failures. */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SupervisedToolTest {
    private static final Duration WAIT = Duration.ofSeconds(20);
    private final Recorder rec = new Recorder();
    private final List<SupervisedTool> started = new ArrayList<>();

    @TempDir
    Path tmp;

    @AfterEach
    void stopAll() {
        started.forEach(SupervisedTool::stop);
    }

    private SupervisedTool tool(ToolSpec spec) {
        SupervisedTool t = new SupervisedTool(spec, rec);
        started.add(t);
        return t;
    }

    private static ToolSpec sh(String name, String script) {
        return ToolSpec.of(name, List.of("sh", "-c", script));
    }

    @Test
    void readyWhenALineMatchesThenStoppedWithItsWholeTree() throws Exception {
        SupervisedTool t = tool(sh("tree", "sleep 300 & echo child $!; echo READY now; wait")
                .withReadiness(Readiness.line("READY"), WAIT));
        t.start();
        assertEquals(ToolState.READY, t.state());
        ProcessHandle shell = t.process();
        assertNotNull(shell);
        long child = Long.parseLong(rec.awaitLine(l -> l.text().startsWith("child "), WAIT).text().substring(6));
        ProcessHandle childHandle = ProcessHandle.of(child).orElseThrow();
        assertTrue(shell.descendants().anyMatch(h -> h.pid() == child), "the sleep is the shell's child");

        t.stop();
        assertEquals(ToolState.STOPPED, t.state());
        assertFalse(shell.isAlive(), "the tool's process is gone");
        assertFalse(childHandle.isAlive(), "and so is the process it started");
        assertEquals(ToolState.STOPPED, t.finished().get(5, TimeUnit.SECONDS));
        assertEquals(List.of(ToolState.STARTING, ToolState.READY, ToolState.STOPPING, ToolState.STOPPED), rec.states("tree"));
    }

    @Test
    void readyWhenThePortAcceptsConnections() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        SupervisedTool t = tool(ToolSpec.of("server", List.of("python3", "-c", """
                import socket, sys
                s = socket.socket(); s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
                s.bind(("127.0.0.1", %d)); s.listen()
                while True: s.accept()[0].close()
                """.formatted(port))).withReadiness(Readiness.ports("127.0.0.1", List.of(port)), WAIT));
        t.start();
        assertFalse(Ports.isFree("127.0.0.1", port), "the tool listens when start returns");
        t.stop();
        assertTrue(Ports.isFree("127.0.0.1", port), "and no longer after stop");
    }

    @Test
    void notReadyInTimeIsAnErrorNamingThePortAndNothingIsLeft() throws Exception {
        int port = Ports.free("127.0.0.1", 1).get(0);
        SupervisedTool t = tool(sh("silent", "echo waiting for nothing; exec sleep 300")
                .withReadiness(Readiness.ports("127.0.0.1", List.of(port)), Duration.ofSeconds(2))); // time for sh to say its line
        ToolException e = assertThrows(ToolException.class, t::start);
        assertTrue(e.getMessage().contains("tool 'silent': not ready within"), e.getMessage());
        assertTrue(e.getMessage().contains("127.0.0.1:[" + port + "]"), e.getMessage());
        assertTrue(e.getMessage().contains("waiting for nothing"), "the last output helps: " + e.getMessage());
        assertEquals(ToolState.FAILED, t.state());
        assertNull(t.process(), "no process is left");
    }

    @Test
    void endingBeforeReadyReportsTheExitCodeAndOutput() {
        SupervisedTool t = tool(sh("quitter", "echo cannot open device >&2; exit 4")
                .withReadiness(Readiness.line("ready"), WAIT));
        ToolException e = assertThrows(ToolException.class, t::start);
        assertTrue(e.getMessage().contains("exited with exit code 4 before it was ready"), e.getMessage());
        assertTrue(e.getMessage().contains("cannot open device"), e.getMessage());
        assertEquals(ToolState.FAILED, t.state());
        assertEquals(4, t.lastExitCode());
    }

    @Test
    void missingProgramsAreNamed() {
        ToolException onPath = assertThrows(ToolException.class,
                () -> tool(ToolSpec.of("ghost", List.of("stagecraft-no-such-program-xyz"))).start());
        assertTrue(onPath.getMessage().contains("tool 'ghost': cannot run 'stagecraft-no-such-program-xyz'"), onPath.getMessage());
        assertTrue(onPath.getMessage().contains("no such program on the PATH"), onPath.getMessage());
        ToolException byPath = assertThrows(ToolException.class,
                () -> tool(ToolSpec.of("ghost2", List.of("/nonexistent/bin/player"))).start());
        assertTrue(byPath.getMessage().contains("cannot run '/nonexistent/bin/player': no such file"), byPath.getMessage());
        ToolException dir = assertThrows(ToolException.class,
                () -> tool(ToolSpec.of("nodir", List.of("true")).withWorkingDir(tmp.resolve("missing"))).start());
        assertTrue(dir.getMessage().contains("working directory " + tmp.resolve("missing") + " does not exist"), dir.getMessage());
    }

    @Test
    void aCrashIsRestartedAsThePolicySaysThenLeftDown() throws Exception {
        SupervisedTool t = tool(sh("flaky", "echo ready; read line; echo crashing; exit 3")
                .withReadiness(Readiness.line("^ready$"), WAIT).withRestart(RestartPolicy.onFailure(1)));
        t.start();
        long firstPid = t.process().pid();
        t.write("crash\n");
        rec.awaitChange(c -> c.to() == ToolState.READY && c.detail().startsWith("ready again"), WAIT);
        assertEquals(1, t.restarts());
        assertEquals(3, t.lastExitCode());
        assertTrue(t.process().pid() != firstPid, "a new process");
        assertTrue(rec.lines.stream().anyMatch(l -> l.stream() == ToolListener.Stream.SUPERVISOR
                && l.text().contains("exit code 3; restart 1 of 1")), rec.lines.toString());

        t.write("crash again\n");
        assertEquals(ToolState.FAILED, t.finished().get(20, TimeUnit.SECONDS));
        assertEquals(List.of(ToolState.STARTING, ToolState.READY, ToolState.RESTARTING, ToolState.STARTING,
                ToolState.READY, ToolState.FAILED), rec.states("flaky"));
        assertTrue(rec.lines.stream().anyMatch(l -> l.text().contains("not restarted (1 of 1 restarts used)")));
    }

    @Test
    void exitCodeZeroEndsOnFailureToolsButAlwaysRestartsAlwaysTools() throws Exception {
        SupervisedTool once = tool(sh("once", "echo ready").withRestart(RestartPolicy.onFailure(3)));
        once.start();
        assertEquals(ToolState.EXITED, once.finished().get(20, TimeUnit.SECONDS));
        assertEquals(0, once.restarts());

        SupervisedTool again = tool(sh("again", "echo ready").withRestart(RestartPolicy.always(2)));
        again.start();
        assertEquals(ToolState.EXITED, again.finished().get(20, TimeUnit.SECONDS));
        assertEquals(2, again.restarts());
    }

    @Test
    void environmentAndWorkingDirectoryAreGiven() throws Exception {
        SupervisedTool t = tool(sh("env", "echo \"$STAGECRAFT_TEST_VAR in $(pwd)\"").withWorkingDir(tmp)
                .withEnvironment(Map.of("STAGECRAFT_TEST_VAR", "hello")));
        t.start();
        String expected = "hello in " + tmp.toRealPath();
        rec.awaitLine(l -> l.text().equals(expected), WAIT);
        assertEquals(ToolState.EXITED, t.finished().get(20, TimeUnit.SECONDS));
    }

    @Test
    void restartPolicyText() {
        assertEquals(RestartPolicy.onFailure(2), RestartPolicy.parse("on-failure:2"));
        assertEquals(RestartPolicy.always(3), RestartPolicy.parse("always"));
        assertEquals(RestartPolicy.NEVER, RestartPolicy.parse(""));
        assertEquals("on-failure:2", RestartPolicy.onFailure(2).text());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> RestartPolicy.parse("sometimes"));
        assertTrue(e.getMessage().contains("'sometimes'"));
    }
}
