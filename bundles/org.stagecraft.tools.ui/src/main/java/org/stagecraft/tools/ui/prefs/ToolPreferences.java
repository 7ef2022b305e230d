package org.stagecraft.tools.ui.prefs;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.core.runtime.preferences.DefaultScope;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.osgi.service.prefs.BackingStoreException;
import org.osgi.service.prefs.Preferences;
import org.stagecraft.tools.types.ToolDefinition;

/**
 * The Tool Manager's settings, stored as ordinary Eclipse preferences of this plug-in (instance
 * scope, i.e. per workspace): the Player and Python programs, and the user's tools, one child node
 * per tool under {@code tools/} (the node name is a sequence number so that tools keep their order).
 */
public final class ToolPreferences {
    public static final String NODE = "org.stagecraft.tools.ui";
    /** The Player program: a path, or a name looked up on PATH. */
    public static final String PLAYER = "playerProgram";
    /** The Python interpreter for robot programs when PyDev is not installed. */
    public static final String PYTHON = "pythonInterpreter";
    public static final String DEFAULT_PLAYER = "player";
    public static final String DEFAULT_PYTHON = "python3";
    private static final String TOOLS = "tools";

    private ToolPreferences() {
    }

    private static IEclipsePreferences node() {
        return InstanceScope.INSTANCE.getNode(NODE);
    }

    static void initializeDefaults() {
        IEclipsePreferences d = DefaultScope.INSTANCE.getNode(NODE);
        d.put(PLAYER, DEFAULT_PLAYER);
        d.put(PYTHON, DEFAULT_PYTHON);
    }

    public static String get(String key) {
        String fallback = PLAYER.equals(key) ? DEFAULT_PLAYER : PYTHON.equals(key) ? DEFAULT_PYTHON : "";
        String v = node().get(key, DefaultScope.INSTANCE.getNode(NODE).get(key, fallback));
        return v == null || v.isBlank() ? fallback : v.trim();
    }

    public static void set(String key, String value) throws BackingStoreException {
        node().put(key, value);
        node().flush();
    }

    public static List<ToolDefinition> tools() {
        List<ToolDefinition> out = new ArrayList<>();
        try {
            Preferences tools = node().node(TOOLS);
            List<String> children = new ArrayList<>(List.of(tools.childrenNames()));
            children.sort((a, b) -> Integer.compare(number(a), number(b)));
            for (String child : children) {
                Preferences t = tools.node(child);
                out.add(new ToolDefinition(t.get("name", child), t.get("type", null), t.get("command", ""),
                        t.get("arguments", ""), t.get("workingDir", ""), environment(t.get("environment", "")),
                        t.get("readiness", ""), t.get("restart", "never"), t.getInt("readyWithinSeconds", 30),
                        t.getBoolean("enabled", true)));
            }
        } catch (BackingStoreException e) {
            throw new IllegalStateException("cannot read the tool preferences: " + e.getMessage(), e);
        }
        return out;
    }

    public static void setTools(List<ToolDefinition> definitions) throws BackingStoreException {
        Preferences tools = node().node(TOOLS);
        tools.removeNode();
        tools = node().node(TOOLS);
        int i = 0;
        for (ToolDefinition d : definitions) {
            Preferences t = tools.node(String.valueOf(i++));
            t.put("name", d.name());
            t.put("type", d.type());
            t.put("command", d.command());
            t.put("arguments", d.arguments());
            t.put("workingDir", d.workingDir());
            t.put("environment", environmentText(d.environment()));
            t.put("readiness", d.readiness());
            t.put("restart", d.restart());
            t.putInt("readyWithinSeconds", d.readyWithinSeconds());
            t.putBoolean("enabled", d.enabled());
        }
        node().flush();
    }

    /** "KEY=value" lines. */
    public static Map<String, String> environment(String text) {
        Map<String, String> env = new LinkedHashMap<>();
        for (String line : text.split("\n")) {
            int eq = line.indexOf('=');
            if (eq > 0) {
                env.put(line.substring(0, eq).trim(), line.substring(eq + 1));
            }
        }
        return env;
    }

    public static String environmentText(Map<String, String> env) {
        StringBuilder s = new StringBuilder();
        env.forEach((k, v) -> s.append(k).append('=').append(v).append('\n'));
        return s.toString();
    }

    private static int number(String s) {
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException e) {
            return Integer.MAX_VALUE;
        }
    }
}
