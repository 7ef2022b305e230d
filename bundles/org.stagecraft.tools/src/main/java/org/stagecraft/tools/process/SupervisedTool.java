package org.stagecraft.tools.process;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.tools.process.ToolListener.Stream;

/**
 * Runs one external tool and watches it: output line by line to a {@link ToolListener}, a readiness
 * check at every start, exit codes, restarts as its {@link RestartPolicy} says, and a stop that takes
 * the whole process tree down. {@link #start()} returns only once the tool is ready; if it is not,
 * nothing of it is left running.
 */
public final class SupervisedTool {
    private static final long POLL_MILLIS = 50;
    /** Connect within 250 ms; a server that accepted sends its banner at once, 2 s is generous. */
    private static final PortProbe PROBE = new PortProbe(250, 2000);
    private static final Duration STOP_GRACE = Duration.ofSeconds(5);

    private final ToolSpec spec;
    private final ToolListener listener;
    private final ProcessStarter starter;
    private final CompletableFuture<ToolState> finished = new CompletableFuture<>();
    private ToolState state = ToolState.NEW;
    private @Nullable Run current;
    private int restarts;
    private @Nullable Integer lastExitCode;
    private boolean stopRequested;
    private boolean firstStartPending = true;

    /** One process of the tool (a restart makes a new one). */
    private final class Run {
        final Process process;
        /** The OS process (a pty4j process has a pid but no handle of its own). */
        final ProcessHandle handle;
        final CountDownLatch exited = new CountDownLatch(1);
        final CountDownLatch lineSeen = new CountDownLatch(1);
        final List<Thread> readers = new ArrayList<>();
        volatile int exitCode;
        volatile boolean ready;
        /** Ended while the first start was still checking readiness; start() decides what that means. */
        boolean exitDeferred;

        Run(Process process) {
            this.process = process;
            this.handle = ProcessHandle.of(process.pid()).orElse(null);
        }
    }

    public SupervisedTool(ToolSpec spec, ToolListener listener) {
        this(spec, listener, ProcessStarter.fromSystemProperties());
    }

    public SupervisedTool(ToolSpec spec, ToolListener listener, ProcessStarter starter) {
        this.spec = spec;
        this.listener = listener == null ? ToolListener.NONE : listener;
        this.starter = starter;
    }

    public ToolSpec spec() {
        return spec;
    }

    public String name() {
        return spec.name();
    }

    public synchronized ToolState state() {
        return state;
    }

    public synchronized int restarts() {
        return restarts;
    }

    /** The exit code of the last process that ended, or null if none has. */
    public synchronized @Nullable Integer lastExitCode() {
        return lastExitCode;
    }

    /** The running process, if any. */
    public synchronized @Nullable ProcessHandle process() {
        return current != null && current.process.isAlive() ? current.handle : null;
    }

    /** Completes with the final state (stopped, exited or failed) once the tool is down for good. */
    public CompletableFuture<ToolState> finished() {
        return finished;
    }

    /**
     * Starts the tool and waits until it is ready.
     *
     * @throws ToolException if it cannot be started, ends before it is ready, or is not ready in time;
     *                       then no process of it is left
     */
    public void start() throws ToolException {
        Run run;
        synchronized (this) {
            if (state != ToolState.NEW) {
                throw new IllegalStateException("tool '" + name() + "' was already started");
            }
            setState(ToolState.STARTING, "starting " + String.join(" ", spec.command()));
            try {
                run = launch();
            } catch (ToolException e) {
                setState(ToolState.FAILED, e.getMessage());
                throw e;
            }
        }
        String failure = awaitReady(run);
        if (failure != null) {
            String message = "tool '" + name() + "': " + failure;
            kill(run);
            synchronized (this) {
                firstStartPending = false;
                if (!state.isFinal()) {
                    setState(ToolState.FAILED, message);
                }
            }
            throw new ToolException(message + lastOutput(run));
        }
        synchronized (this) {
            firstStartPending = false;
            if (stopRequested) {
                throw new ToolException("tool '" + name() + "' was stopped while it started");
            }
            run.ready = true;
            setState(ToolState.READY, "ready: " + spec.readiness().describe());
            if (run.exitDeferred) {
                // it was ready and has already ended: now the restart policy decides
                Thread.ofVirtual().name("tool-exit-" + name()).start(() -> exited(run, run.exitCode));
            }
        }
    }

    /** Sends text to the tool's standard input (what a user types into its console). */
    public void write(String text) throws IOException {
        Run run;
        synchronized (this) {
            run = current;
        }
        if (run == null || !run.process.isAlive()) {
            throw new IOException("tool '" + name() + "' is not running");
        }
        OutputStream in = run.process.getOutputStream();
        in.write(text.getBytes(StandardCharsets.UTF_8));
        in.flush();
    }

    /**
     * Stops the tool and every process it started, and waits until they are gone. Its output up to
     * the end has been passed on when this returns.
     */
    public void stop() {
        Run run;
        synchronized (this) {
            stopRequested = true;
            if (state.isFinal() || state == ToolState.NEW) {
                if (state == ToolState.NEW) {
                    setState(ToolState.STOPPED, "never started");
                }
                return;
            }
            setState(ToolState.STOPPING, "stopping");
            run = current;
        }
        if (run != null) {
            kill(run);
        }
        synchronized (this) {
            if (!state.isFinal()) {
                setState(ToolState.STOPPED, run != null ? "stopped (exit code " + run.exitCode + ")" : "stopped");
            }
        }
    }

    // ---- inside -------------------------------------------------------------------------------

    /** Called with the lock held. */
    private Run launch() throws ToolException {
        if (spec.workingDir() != null && !Files.isDirectory(spec.workingDir())) {
            throw new ToolException("tool '" + name() + "': working directory " + spec.workingDir() + " does not exist");
        }
        ProcessStarter.Started started;
        try {
            started = starter.start(spec.command(), spec.workingDir(), spec.environment());
        } catch (IOException e) {
            throw new ToolException("tool '" + name() + "': cannot run '" + spec.command().get(0) + "': " + why(e), e);
        }
        Process p = started.process();
        Run run = new Run(p);
        current = run;
        String note = started.note();
        if (note != null) {
            output(Stream.SUPERVISOR, note);
        }
        output(Stream.SUPERVISOR, "started " + String.join(" ", spec.command()) + " (pid " + p.pid() + ")");
        // if the IDE dies without stopping it (killed, crashed), the reaper takes the tool's tree down
        String unprotected = OrphanReaper.shared().register(p.pid());
        if (unprotected != null) {
            output(Stream.SUPERVISOR, unprotected);
        }
        if (started.onTerminal()) {
            output(Stream.SUPERVISOR, "output through a pseudo-terminal (each line as it is written)");
        }
        run.readers.add(reader(run, p.getInputStream(), Stream.STDOUT));
        run.readers.add(reader(run, p.getErrorStream(), Stream.STDERR));
        // Platform threads: a pty's reads and waits are native calls that would pin a virtual
        // thread's carrier, and three per tool soon starve the spy's virtual threads.
        Thread.ofPlatform().daemon().name("tool-watch-" + name()).start(() -> watch(run));
        return run;
    }

    private String why(IOException e) {
        String m = String.valueOf(e.getMessage());
        // "error=2," before JDK 22, "error: 2 (No such file or directory)" since
        boolean notFound = m.contains("error=2,") || m.contains("error: 2 ") || m.contains("No such file or directory");
        String cmd = spec.command().get(0);
        if (notFound) {
            return cmd.contains("/") ? "no such file" : "no such program on the PATH (" + System.getenv("PATH") + ")";
        }
        int i = m.indexOf("error");
        return i >= 0 ? m.substring(i) : m;
    }

    private Thread reader(Run run, InputStream in, Stream stream) {
        return Thread.ofPlatform().daemon().name("tool-" + stream.name().toLowerCase() + "-" + name()).start(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
                for (String line = r.readLine(); line != null; line = r.readLine()) {
                    if (spec.readiness() instanceof Readiness.OutputLine l && l.pattern().matcher(line).find()) {
                        run.lineSeen.countDown();
                    }
                    remember(run, line);
                    listener.output(this, stream, line);
                }
            } catch (IOException e) {
                // the process is gone; its exit is reported by the watcher
            }
        });
    }

    private final Object tailLock = new Object();
    private final java.util.ArrayDeque<String> tail = new java.util.ArrayDeque<>();

    private void remember(Run run, String line) {
        synchronized (tailLock) {
            tail.addLast(line);
            while (tail.size() > 5) {
                tail.removeFirst();
            }
        }
    }

    private String lastOutput(Run run) {
        synchronized (tailLock) {
            return tail.isEmpty() ? "" : "; its last output:\n  " + String.join("\n  ", tail);
        }
    }

    private void watch(Run run) {
        int code;
        while (true) {
            try {
                code = run.process.waitFor();
                break;
            } catch (InterruptedException e) {
                // not interrupted by anyone but the JVM going down; keep waiting
            }
        }
        // at once: from now on the pid may be reused by a process that is none of ours
        OrphanReaper.shared().unregister(run.process.pid());
        // Let the readers pass on the last lines before the exit is reported.
        for (Thread t : run.readers) {
            try {
                t.join(TimeUnit.SECONDS.toMillis(2));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        run.exitCode = code;
        synchronized (this) {
            // before anyone can see the run as ended: a start that fails on it reports this code
            lastExitCode = code;
        }
        run.exited.countDown();
        exited(run, code);
    }

    private void exited(Run run, int code) {
        boolean restart;
        synchronized (this) {
            lastExitCode = code;
            if (run != current || stopRequested) {
                output(Stream.SUPERVISOR, "exited with " + exitText(code));
                return;
            }
            if (!run.ready && firstStartPending) {
                // The first start's caller decides: not ready yet is its error, ready is the policy's case.
                run.exitDeferred = true;
                return;
            }
            restart = spec.restart().restartAfter(code, restarts);
            if (!restart) {
                ToolState end = code == 0 ? ToolState.EXITED : ToolState.FAILED;
                output(Stream.SUPERVISOR, "exited with " + exitText(code)
                        + (spec.restart().mode() == RestartPolicy.Mode.NEVER || code == 0 && spec.restart().mode() == RestartPolicy.Mode.ON_FAILURE
                                ? "" : "; not restarted (" + restarts + " of " + spec.restart().maxRestarts() + " restarts used)"));
                setState(end, "exited with " + exitText(code));
                return;
            }
            restarts++;
            setState(ToolState.RESTARTING, "exited with " + exitText(code) + "; restart " + restarts + " of "
                    + spec.restart().maxRestarts());
        }
        Run next;
        synchronized (this) {
            if (stopRequested) {
                return;
            }
            setState(ToolState.STARTING, "restarting");
            try {
                next = launch();
            } catch (ToolException e) {
                setState(ToolState.FAILED, e.getMessage());
                return;
            }
        }
        String failure = awaitReady(next);
        if (failure != null) {
            output(Stream.SUPERVISOR, failure);
            // Its watcher sees the exit and the policy decides again (the restarts are bounded).
            if (next.process.isAlive()) {
                kill(next);
            }
            return;
        }
        synchronized (this) {
            if (next == current && !stopRequested) {
                next.ready = true;
                setState(ToolState.READY, "ready again: " + spec.readiness().describe());
            }
        }
    }

    /** Null when ready, else why not. */
    private @Nullable String awaitReady(Run run) {
        long deadline = System.nanoTime() + spec.readyWithin().toNanos();
        Set<Integer> open = new HashSet<>();
        while (true) {
            boolean ready = switch (spec.readiness()) {
                case Readiness.Started s -> true;
                case Readiness.OutputLine l -> run.lineSeen.getCount() == 0;
                case Readiness.PortsOpen p -> {
                    for (int port : p.ports()) {
                        if (!open.contains(port) && PROBE.isOpen(p.host(), port, p.bannerBytes())) {
                            open.add(port);
                        }
                    }
                    yield open.size() == p.ports().size();
                }
            };
            if (ready) {
                return null;
            }
            if (run.exited.getCount() == 0) {
                return "exited with " + exitText(run.exitCode) + " before it was ready (waiting for "
                        + spec.readiness().describe() + ")";
            }
            synchronized (this) {
                if (stopRequested) {
                    return "stopped while starting";
                }
            }
            if (System.nanoTime() > deadline) {
                String missing = "";
                if (spec.readiness() instanceof Readiness.PortsOpen p) {
                    List<Integer> closed = new ArrayList<>(p.ports());
                    closed.removeAll(open);
                    missing = " (not open: " + p.host() + ":" + closed + ")";
                }
                return "not ready within " + spec.readyWithin().toSeconds() + " s: no " + spec.readiness().describe()
                        + missing;
            }
            try {
                // waiting on the exit latch: an exit ends the wait at once
                run.exited.await(POLL_MILLIS, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return "interrupted while waiting for " + spec.readiness().describe();
            }
        }
    }

    private void kill(Run run) {
        List<ProcessHandle> tree = run.handle != null ? ProcessTree.stop(run.handle, STOP_GRACE) : List.of();
        if (run.handle == null) {
            run.process.destroyForcibly();
        }
        if (tree.size() > 1) {
            output(Stream.SUPERVISOR, "stopped " + tree.size() + " processes (pids "
                    + String.join(", ", tree.stream().map(h -> String.valueOf(h.pid())).toList()) + ")");
        }
        try {
            if (!run.exited.await(15, TimeUnit.SECONDS)) {
                output(Stream.SUPERVISOR, "pid " + run.process.pid() + " did not end after SIGKILL");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    static String exitText(int code) {
        return code > 128 && code < 160 ? "exit code " + code + " (signal " + (code - 128) + ")" : "exit code " + code;
    }

    private void output(Stream stream, String line) {
        listener.output(this, stream, line);
    }

    /** Called with the lock held, so listeners see the changes in order. */
    private void setState(ToolState to, String detail) {
        ToolState from = state;
        state = to;
        output(Stream.SUPERVISOR, to.name().toLowerCase() + ": " + detail);
        listener.stateChanged(this, from, to, detail);
        if (to.isFinal()) {
            finished.complete(to);
        }
    }

    @Override
    public String toString() {
        return "tool '" + name() + "' (" + state() + ")";
    }
}
