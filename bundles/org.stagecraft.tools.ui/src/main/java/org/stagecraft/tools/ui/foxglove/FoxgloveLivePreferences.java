package org.stagecraft.tools.ui.foxglove;

import java.net.InetSocketAddress;

import org.eclipse.core.runtime.preferences.DefaultScope;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.osgi.service.prefs.BackingStoreException;
import org.stagecraft.spy.proxy.Route;
import org.stagecraft.tools.ui.prefs.ToolPreferences;

/**
 * The live view's two settings, Eclipse preferences of this plug-in (per workspace): whether the
 * workbench's live streams are served over the Foxglove WebSocket protocol, and where.
 */
public final class FoxgloveLivePreferences {
    public static final String ENABLED = "foxgloveLive";
    public static final String ADDRESS = "foxgloveLiveAddress";
    /** Foxglove's usual port, on loopback: other machines reach it only when the user says so. */
    public static final String DEFAULT_ADDRESS = "127.0.0.1:8765";

    private FoxgloveLivePreferences() {
    }

    static IEclipsePreferences node() {
        return InstanceScope.INSTANCE.getNode(ToolPreferences.NODE);
    }

    public static void initializeDefaults() {
        IEclipsePreferences d = DefaultScope.INSTANCE.getNode(ToolPreferences.NODE);
        d.putBoolean(ENABLED, false);
        d.put(ADDRESS, DEFAULT_ADDRESS);
    }

    public static boolean enabled() {
        return node().getBoolean(ENABLED, false);
    }

    public static String addressText() {
        String v = node().get(ADDRESS, DEFAULT_ADDRESS);
        return v == null || v.isBlank() ? DEFAULT_ADDRESS : v.trim();
    }

    /**
     * {@code [ADDR:]PORT}, the address defaulting to loopback.
     *
     * @throws IllegalArgumentException naming what is wrong
     */
    public static InetSocketAddress parse(String text) {
        return Route.address(text.trim(), "127.0.0.1");
    }

    public static void set(boolean enabled, String address) throws BackingStoreException {
        node().putBoolean(ENABLED, enabled);
        node().put(ADDRESS, address);
        node().flush();
    }

    public static void setEnabled(boolean enabled) throws BackingStoreException {
        node().putBoolean(ENABLED, enabled);
        node().flush();
    }
}
