package org.stagecraft.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.Proxy;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.replay.fields.StreamCondition;
import org.stagecraft.spy.breakpoint.BreakpointHit;
import org.stagecraft.spy.breakpoint.BreakpointListener;
import org.stagecraft.spy.breakpoint.DataBreakpoint;
import org.stagecraft.spy.breakpoint.DataBreakpoints;
import org.stagecraft.spy.proxy.NetworkSpy;

/**
 * {@code stagecraft spy --break}: robot data breakpoints without the IDE, e.g. for a robot on a lab
 * machine. Sets the breakpoints on the spy (and enables its robot holds, before the first program
 * connects), says each hit and when it ends on stderr, and releases the robots when a line is read
 * from the keys (Enter on the terminal) or on SIGUSR1.
 */
final class BreakConsole {
    static final String SIGNAL = "USR1";

    private final DataBreakpoints breakpoints;
    private final PrintStream err;
    private final boolean tty;
    private final AtomicLong hits = new AtomicLong();

    BreakConsole(NetworkSpy spy, List<StreamCondition> conditions, Duration wait, PrintStream err, boolean tty) {
        this.breakpoints = spy.dataBreakpoints();
        this.err = err;
        this.tty = tty;
        spy.holds().setEnabled(true); // a hit holds the robots: connections must be holdable from the first
        breakpoints.setEnabled(true);
        breakpoints.passOnBound(wait);
        breakpoints.untilFalse(true); // released, a robot must be able to drive away from what stopped it
        for (int i = 0; i < conditions.size(); i++) {
            breakpoints.add(new DataBreakpoint("--break " + (i + 1), conditions.get(i)));
        }
        breakpoints.addListener(new BreakpointListener() {
            @Override
            public void hit(BreakpointHit h) {
                hits.incrementAndGet();
                say(String.format(Locale.ROOT, "BREAK %s, connection %d at byte %d of Player's stream (seq %d, time %.3f):"
                        + " robots held; press Enter or send SIG%s (kill -%s %d) to release", h.description(),
                        h.connection().id(), h.offset(), h.header().seqUnsigned(), h.header().timestamp(), SIGNAL, SIGNAL,
                        ProcessHandle.current().pid()));
            }

            @Override
            public void passedOn(BreakpointHit h) {
                say(String.format(Locale.ROOT, "the triggering message and what followed went on to the program after %.1f ms",
                        h.heldNanos() / 1e6));
            }

            @Override
            public void resumed(BreakpointHit h) {
                say("released: the robots move again; this breakpoint stops again once its condition has stopped holding");
            }
        });
    }

    /** Releases on each line of {@code keys}, and on SIGUSR1 where the JVM lets us catch it. */
    void start(InputStream keys) {
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(keys, StandardCharsets.UTF_8))) {
                while (r.readLine() != null) {
                    breakpoints.resume();
                }
            } catch (IOException e) {
                // no keys: the signal still releases
            }
        }, "stagecraft-spy-break-keys");
        t.setDaemon(true);
        t.start();
        @Nullable String why = onSignal(SIGNAL, breakpoints::resume);
        if (why != null) {
            say("SIG" + SIGNAL + " cannot release holds here (" + why + "); Enter does");
        }
    }

    String status() {
        return breakpoints.current() != null ? "HELD at a robot data breakpoint (Enter releases)"
                : hits.get() + " breakpoint hits";
    }

    String totals() {
        return hits.get() + " robot data breakpoint hits";
    }

    private void say(String line) {
        err.print((tty ? "\n" : "") + "stagecraft spy: " + line + "\n");
        err.flush();
    }

    /**
     * Runs {@code action} on the named signal through {@code sun.misc.Signal}, found at run time: the
     * command line runs on the class path, where the JDK's jdk.unsupported module has it, and this
     * bundle must not import it under OSGi. Returns why not, or null.
     */
    static @Nullable String onSignal(String name, Runnable action) {
        try {
            Class<?> signal = Class.forName("sun.misc.Signal");
            Class<?> handler = Class.forName("sun.misc.SignalHandler");
            InvocationHandler call = (proxy, method, args) -> {
                if (method.getName().equals("handle")) {
                    action.run();
                }
                return null;
            };
            Object h = Proxy.newProxyInstance(handler.getClassLoader(), new Class<?>[] { handler }, call);
            Object s = signal.getConstructor(String.class).newInstance(name);
            signal.getMethod("handle", signal, handler).invoke(null, s, h);
            return null;
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            Throwable cause = e.getCause() != null ? e.getCause() : e;
            return cause.getMessage() != null ? cause.getMessage() : cause.getClass().getSimpleName();
        }
    }
}
