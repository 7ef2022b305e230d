package org.stagecraft.tools.world;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.spy.hold.HoldListener;
import org.stagecraft.spy.hold.HoldState;
import org.stagecraft.spy.hold.WorldChange;
import org.stagecraft.spy.proxy.NetworkSpy;

/**
 * Freezes the session's simulated world while its robots are held, for whatever reason (the program suspended
 * in the debugger, the emergency stop, a robot data breakpoint, the watchdog), and lets it run on when the hold
 * ends. The robots are held first (their zero commands have gone to Player when the hold reports), then the
 * world stops; each freeze and thaw is logged by the spy as the session's own. Requests to the world driver
 * run on a thread of their own, in the order the hold changed.
 */
public final class WorldFreeze implements HoldListener, AutoCloseable {
    /** Told on the freezing thread after each freeze and thaw, and when the world driver fails. */
    public interface Listener {
        void worldChanged(WorldState state, @Nullable String problem);
    }

    /** Opens a channel to the world driver (again after Player restarted). */
    public interface Opener {
        WorldChannel open() throws WorldException;
    }

    private final Opener opener;
    private @Nullable WorldChannel channel; // only on the freezing thread
    private final NetworkSpy spy;
    private final Consumer<String> say;
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "stagecraft-world-freeze");
        t.setDaemon(true);
        return t;
    });
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();

    // only on the freezing thread
    private boolean frozen;
    private long frozenAtNanos;
    private boolean failedOnce;
    private volatile @Nullable WorldState last;

    /**
     * @param say where the session tells its user what went wrong (its console)
     */
    public WorldFreeze(WorldChannel channel, Opener opener, NetworkSpy spy, Consumer<String> say) {
        this.channel = channel;
        this.opener = opener;
        this.spy = spy;
        this.say = say;
    }

    public void addListener(Listener l) {
        listeners.add(l);
    }

    public void removeListener(Listener l) {
        listeners.remove(l);
    }

    /** The world's state after the last freeze or thaw, or null before the first. */
    public @Nullable WorldState last() {
        return last;
    }

    @Override
    public void holdChanged(HoldState state) {
        boolean want = state.held();
        String why = state.reasons().keySet().stream().map(r -> r.text()).reduce((a, b) -> a + ", " + b).orElse("");
        long heldAt = System.nanoTime();
        try {
            thread.execute(() -> apply(want, why, heldAt));
        } catch (java.util.concurrent.RejectedExecutionException e) {
            // closed: the session is ending and Player with it
        }
    }

    private void apply(boolean want, String why, long heldAt) {
        if (want == frozen) {
            return;
        }
        try {
            WorldState s = request(want);
            long now = System.nanoTime();
            frozen = want;
            last = s;
            failedOnce = false; // a later failure is news again
            String text;
            if (want) {
                frozenAtNanos = now;
                text = String.format(Locale.ROOT, "world frozen at simulated time %s (%s), %.1f ms after the hold", s.simTime(),
                        why, (now - heldAt) / 1e6);
            } else {
                text = String.format(Locale.ROOT, "world runs on from simulated time %s after %.2f s frozen", s.simTime(),
                        (now - frozenAtNanos) / 1e9);
            }
            spy.worldChanged(new WorldChange(want, s.simTimeMicros(), text));
            for (Listener l : listeners) {
                l.worldChanged(s, null);
            }
        } catch (WorldException e) {
            String problem = "the simulated world could not be " + (want ? "frozen" : "thawed") + ": " + e.getMessage();
            if (!failedOnce) {
                say.accept(problem);
                failedOnce = true;
            }
            WorldState s = last;
            for (Listener l : listeners) {
                l.worldChanged(s != null ? s : new WorldState(false, 0, false), problem);
            }
        }
    }

    private WorldState request(boolean frozenWanted) throws WorldException {
        return ask(c -> c.set(frozenWanted));
    }

    /** One request to the driver, on this thread. */
    private interface Request {
        WorldState send(WorldChannel channel) throws WorldException;
    }

    /**
     * Asks the driver; when the channel has broken (Player was restarted by its restart policy, and with it the
     * driver), opens a new one and asks once more.
     */
    private WorldState ask(Request request) throws WorldException {
        WorldChannel c = channel;
        if (c != null) {
            try {
                return request.send(c);
            } catch (WorldException e) {
                c.close();
                channel = null;
            }
        }
        WorldChannel fresh = opener.open();
        channel = fresh;
        return request.send(fresh);
    }

    /**
     * Brings Stage's window to the front, on the freeze's thread (after any freeze or thaw asked before).
     * Completes with the world's state (its {@code gui} false: there is no window), or with the
     * {@link WorldException} saying why it could not.
     */
    public java.util.concurrent.CompletableFuture<WorldState> raiseWindow() {
        java.util.concurrent.CompletableFuture<WorldState> done = new java.util.concurrent.CompletableFuture<>();
        try {
            thread.execute(() -> {
                try {
                    done.complete(ask(WorldChannel::raiseWindow));
                } catch (WorldException e) {
                    done.completeExceptionally(e);
                }
            });
        } catch (java.util.concurrent.RejectedExecutionException e) {
            done.completeExceptionally(new WorldException("the session has ended"));
        }
        return done;
    }

    /** Thaws the world if it is frozen (a session that ends leaves no frozen world behind), then closes the channel. */
    @Override
    public void close() {
        try {
            thread.execute(() -> apply(false, "", System.nanoTime()));
        } catch (java.util.concurrent.RejectedExecutionException e) {
            return; // closed already
        }
        thread.execute(() -> {
            WorldChannel c = channel;
            if (c != null) {
                c.close();
            }
        });
        thread.shutdown();
        try {
            thread.awaitTermination(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
