package org.stagecraft.demo.ui;

import java.nio.file.Path;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.demo.PlayerChoice;

/**
 * What {@code ./stagecraft demo} asked for, passed as system properties (the product is started with
 * {@code java -jar}, and a property reaches an early-startup class without parsing the application's
 * arguments).
 *
 * @param enabled          the product was started as the demo
 * @param status           where to write the demo's status (JSON), or null
 * @param exitAfterSeconds close the workbench this long after the start (0: stay open)
 * @param player           "auto" (a real {@code player} on PATH if there is one, else the recording),
 *                         "recorded", or the path of a Player program
 * @param recording        a recording to use instead of the shipped one, or null
 * @param python           the Python interpreter for the robot program with a real Player (one with
 *                         pint, set up by {@code ./stagecraft demo}), or null for the preference
 */
record DemoOptions(boolean enabled, @Nullable Path status, int exitAfterSeconds, String player, @Nullable Path recording, @Nullable String python) {
    static final String PREFIX = "stagecraft.demo";

    static DemoOptions fromSystemProperties() {
        boolean enabled = Boolean.parseBoolean(System.getProperty(PREFIX, "false"));
        String status = System.getProperty(PREFIX + ".status", "");
        String player = System.getProperty(PREFIX + ".player", "");
        String recording = System.getProperty(PREFIX + ".recording", "");
        String python = System.getProperty(PREFIX + ".python", "");
        int exitAfter;
        try {
            exitAfter = Math.max(0, Integer.parseInt(System.getProperty(PREFIX + ".exitAfter", "0").trim()));
        } catch (NumberFormatException e) {
            exitAfter = 0;
        }
        return new DemoOptions(enabled, status.isBlank() ? null : Path.of(status), exitAfter,
                player.isBlank() ? PlayerChoice.AUTO : player.trim(), recording.isBlank() ? null : Path.of(recording),
                python.isBlank() ? null : python.trim());
    }
}
