package org.stagecraft.tools.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Tools run on a pseudo-terminal: a program that never flushes (C stdio, or Python without -u,
 * buffers a pipe in blocks) has each line seen as it is written, stdout and stderr stay apart,
 * and without a terminal the tool still runs, on pipes, with a note in its console.
 */
@Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class ToolOutputTerminalTest {
    private static final Duration WAIT = Duration.ofSeconds(20);
    /** Writes a line, never flushes, then sits for a minute: on a pipe the line would come only at exit. */
    private static final List<String> UNFLUSHED = List.of("python3", "-c", """
            import sys, time
            print("Listening on ports 6665")
            print("to stderr", file=sys.stderr)
            time.sleep(60)
            print("never seen: stopped before")
            """);
    private final Recorder rec = new Recorder();
    private final List<SupervisedTool> started = new ArrayList<>();

    @AfterEach
    void stopAll() {
        started.forEach(SupervisedTool::stop);
    }

    private SupervisedTool tool(ProcessStarter starter) {
        SupervisedTool t = new SupervisedTool(ToolSpec.of("unflushed", UNFLUSHED), rec, starter);
        started.add(t);
        return t;
    }

    @Test
    void aLineWrittenWithoutFlushArrivesWhileTheProgramStillRuns() throws Exception {
        SupervisedTool t = tool(new ProcessStarter(true));
        t.start();
        Recorder.Line line = rec.awaitLine(l -> l.text().equals("Listening on ports 6665"), WAIT);
        assertEquals(ToolListener.Stream.STDOUT, line.stream());
        assertTrue(t.process() != null && t.process().isAlive(), "the program is still running (sleeping 60 s)");
        Recorder.Line err = rec.awaitLine(l -> l.text().equals("to stderr"), WAIT);
        assertEquals(ToolListener.Stream.STDERR, err.stream(), "stderr is kept apart from stdout");
        assertTrue(rec.lines.stream().anyMatch(l -> l.stream() == ToolListener.Stream.SUPERVISOR
                && l.text().contains("pseudo-terminal")), "the console says the tool runs on a terminal");
        t.stop();
        assertFalse(rec.lines.stream().anyMatch(l -> l.text().startsWith("never seen")));
    }

    @Test
    void readinessByALineWorksForABufferingProgram() throws Exception {
        SupervisedTool t = new SupervisedTool(ToolSpec.of("unflushed", UNFLUSHED)
                .withReadiness(Readiness.line("Listening on ports"), WAIT), rec, new ProcessStarter(true));
        started.add(t);
        t.start(); // would time out on a pipe: the line sits in the program's buffer
        assertEquals(ToolState.READY, t.state());
    }

    @Test
    void onPipesTheToolRunsAndTheConsoleSaysSo() throws Exception {
        SupervisedTool t = new SupervisedTool(ToolSpec.of("echo", List.of("sh", "-c", "echo out; echo err >&2")), rec,
                new ProcessStarter(false));
        started.add(t);
        t.start();
        assertEquals(ToolState.EXITED, t.finished().get(20, java.util.concurrent.TimeUnit.SECONDS));
        assertEquals(ToolListener.Stream.STDOUT, rec.awaitLine(l -> l.text().equals("out"), WAIT).stream());
        assertEquals(ToolListener.Stream.STDERR, rec.awaitLine(l -> l.text().equals("err"), WAIT).stream());
        assertFalse(rec.lines.stream().anyMatch(l -> l.text().contains("pseudo-terminal")));
    }

    @Test
    void aMissingProgramIsReportedAsMissingNotAsATerminalProblem() {
        SupervisedTool t = new SupervisedTool(ToolSpec.of("ghost", List.of("stagecraft-no-such-program")), rec,
                new ProcessStarter(true));
        ToolException e = org.junit.jupiter.api.Assertions.assertThrows(ToolException.class, t::start);
        assertTrue(e.getMessage().contains("cannot run 'stagecraft-no-such-program': no such program on the PATH"),
                e.getMessage());
    }
}
