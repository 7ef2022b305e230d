package org.stagecraft.tools.ui.foxglove;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.URI;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.preferences.IEclipsePreferences.IPreferenceChangeListener;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.core.streams.WorkbenchBus;
import org.stagecraft.foxglove.live.BusRelay;
import org.stagecraft.foxglove.live.FoxgloveServer;
import org.stagecraft.foxglove.live.LiveScene;

/**
 * The workbench's live view in Foxglove: while the preference is on, a {@link FoxgloveServer} serves
 * what the workbench bus carries (every Robot Session's spy), converted by {@link LiveScene} as in
 * {@code stagecraft spy --foxglove}. Follows the preferences: turning it on or off, or changing the
 * address, (re)starts or stops the server. One per workbench.
 */
public final class FoxgloveLive {
    private static final String PLUGIN = "org.stagecraft.tools.ui";
    private static final FoxgloveLive INSTANCE = new FoxgloveLive();

    private final List<Runnable> listeners = new CopyOnWriteArrayList<>();
    private final IPreferenceChangeListener follow = e -> {
        if (FoxgloveLivePreferences.ENABLED.equals(e.getKey()) || FoxgloveLivePreferences.ADDRESS.equals(e.getKey())) {
            apply();
        }
    };
    // guarded by this
    private @Nullable FoxgloveServer server;
    private @Nullable BusRelay relay;
    private @Nullable String servingAddress;
    private @Nullable String problem;
    private boolean following;

    private FoxgloveLive() {
    }

    public static FoxgloveLive get() {
        return INSTANCE;
    }

    /** Starts following the preferences (idempotent) and applies them now. */
    public void followPreferences() {
        synchronized (this) {
            if (!following) {
                FoxgloveLivePreferences.node().addPreferenceChangeListener(follow);
                following = true;
            }
        }
        apply();
    }

    /** Serves, stops or moves the server as the preferences say. */
    public void apply() {
        boolean on = FoxgloveLivePreferences.enabled();
        String address = FoxgloveLivePreferences.addressText();
        synchronized (this) {
            if (on && server != null && address.equals(servingAddress)) {
                return;
            }
            stopServing();
            problem = null;
            if (on) {
                try {
                    InetSocketAddress a = FoxgloveLivePreferences.parse(address);
                    FoxgloveServer started = FoxgloveServer.start(a, "Stagecraft", FoxgloveServer.DEFAULT_MAX_QUEUED_FRAMES);
                    server = started;
                    relay = BusRelay.start(WorkbenchBus.get(), started, LiveScene.converter(), BusRelay.DEFAULT_CAPACITY);
                    servingAddress = address;
                    started.onNotice(n -> ILog.of(getClass()).log(new Status(IStatus.INFO, PLUGIN, "Foxglove live view: " + n)));
                } catch (IOException | IllegalArgumentException e) {
                    stopServing();
                    problem = "Foxglove live view: " + e.getMessage();
                    ILog.of(getClass()).log(new Status(IStatus.ERROR, PLUGIN, problem));
                }
            }
        }
        listeners.forEach(Runnable::run);
    }

    /** Stops serving and following (the plug-in stops). */
    public void shutdown() {
        synchronized (this) {
            if (following) {
                FoxgloveLivePreferences.node().removePreferenceChangeListener(follow);
                following = false;
            }
            stopServing();
        }
        listeners.forEach(Runnable::run);
    }

    private void stopServing() {
        if (relay != null) {
            relay.close();
            relay = null;
        }
        if (server != null) {
            server.close();
            server = null;
        }
        servingAddress = null;
    }

    public synchronized boolean isServing() {
        return server != null;
    }

    /** Where viewers connect, or null when not serving. */
    public synchronized @Nullable URI uri() {
        return server == null ? null : server.uri();
    }

    /** Why the last start failed, or null. */
    public synchronized @Nullable String problem() {
        return problem;
    }

    /** The server's counters, or null when not serving. */
    public synchronized FoxgloveServer.@Nullable Counters counters() {
        return server == null ? null : server.counters();
    }

    /** Told (on any thread) whenever serving starts, stops or fails. */
    public void addListener(Runnable r) {
        listeners.add(r);
    }

    public void removeListener(Runnable r) {
        listeners.remove(r);
    }
}
