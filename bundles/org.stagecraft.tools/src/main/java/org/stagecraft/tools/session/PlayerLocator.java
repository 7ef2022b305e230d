package org.stagecraft.tools.session;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Decides which {@code player} a session runs, and with what environment. In this order:
 * <ol>
 * <li>the launch configuration's Player program, if it names one;</li>
 * <li>the Player program preference, if the user set one (the default, plain {@code player}, counts
 * as not set, so that it does not hide the install prefix);</li>
 * <li>{@code bin/player} of the Stagecraft Player/Stage install prefix, the one
 * {@code ./stagecraft player-stage install} writes: {@code $STAGECRAFT_PLAYER_STAGE}, else
 * {@code ${XDG_DATA_HOME:-$HOME/.local/share}/stagecraft/player-stage};</li>
 * <li>{@code player} on the PATH.</li>
 * </ol>
 * A Player from the prefix gets the three variables that make that install work wherever it is
 * (Player and the stageplugin have no RPATH): {@code LD_LIBRARY_PATH=<prefix>/lib} before any
 * existing value, {@code PLAYERPATH=<prefix>/lib} (where Player finds the stageplugin) and
 * {@code STAGEPATH=<prefix>/share/stage:<prefix>/lib/Stage-4.3} (Stage's colour database and
 * controllers). So does a Player named in the launch configuration or the preference that is the
 * {@code bin/player} of such an install anywhere (an install is recognised by the {@code env.sh} that
 * {@code ./stagecraft player-stage install} writes beside {@code bin/}): without those variables it
 * could not even load its own libraries.
 */
public final class PlayerLocator {
    /** Overrides where {@code ./stagecraft player-stage install} put Player and Stage. */
    public static final String PREFIX_VARIABLE = "STAGECRAFT_PLAYER_STAGE";
    public static final String PLAYER_NAME = "player";

    /** Where the Player program came from. */
    public enum Source {
        LAUNCH_CONFIGURATION, PREFERENCE, INSTALL_PREFIX, PATH
    }

    /**
     * The Player to run.
     *
     * @param program     a path, or a name the process starter looks up on the PATH
     * @param prefix      the install prefix it comes from, or null
     * @param environment Player's whole extra environment (the launch's own Player variables included)
     */
    public record Located(String program, Source source, @Nullable Path prefix, Map<String, String> environment) {
        public Located {
            environment = Map.copyOf(environment);
        }
    }

    private final Map<String, String> processEnvironment;

    /** @param processEnvironment the IDE's environment (HOME, XDG_DATA_HOME, PATH, ...) */
    public PlayerLocator(Map<String, String> processEnvironment) {
        this.processEnvironment = Map.copyOf(processEnvironment);
    }

    public static PlayerLocator fromSystem() {
        return new PlayerLocator(System.getenv());
    }

    /** The install prefix, whether or not anything is installed there; null without HOME. */
    public @Nullable Path installPrefix() {
        @Nullable String explicit = processEnvironment.get(PREFIX_VARIABLE);
        if (explicit != null && !explicit.isBlank()) {
            return Path.of(explicit);
        }
        @Nullable String data = processEnvironment.get("XDG_DATA_HOME");
        if (data == null || data.isBlank()) {
            @Nullable String home = processEnvironment.get("HOME");
            if (home == null || home.isBlank()) {
                return null;
            }
            data = Path.of(home, ".local", "share").toString();
        }
        return Path.of(data, "stagecraft", "player-stage");
    }

    /**
     * @param launchSetting      the launch configuration's Player program, or null/blank
     * @param preference         the user's Player program preference, or null/blank when not set
     * @param launchEnvironment  the launch configuration's Player environment (wins over what is found here,
     *                           except that LD_LIBRARY_PATH keeps the prefix's library directory first)
     */
    public Located locate(@Nullable String launchSetting, @Nullable String preference, Map<String, String> launchEnvironment) {
        if (isSet(launchSetting)) {
            return named(launchSetting.trim(), Source.LAUNCH_CONFIGURATION, launchEnvironment);
        }
        if (isSet(preference) && !PLAYER_NAME.equals(preference.trim())) {
            return named(preference.trim(), Source.PREFERENCE, launchEnvironment);
        }
        Path prefix = installPrefix();
        if (prefix != null) {
            Path player = prefix.resolve("bin").resolve(PLAYER_NAME);
            if (Files.isRegularFile(player) && Files.isExecutable(player)) {
                return new Located(player.toString(), Source.INSTALL_PREFIX, prefix, prefixEnvironment(prefix,
                        launchEnvironment));
            }
        }
        // found or not: a missing one is reported by the start as "no such program on the PATH (...)"
        return new Located(PLAYER_NAME, Source.PATH, null, launchEnvironment);
    }

    /** A Player the user named: the prefix's variables too when it is the {@code bin/player} of a Stagecraft install. */
    private Located named(String program, Source source, Map<String, String> launchEnvironment) {
        Path prefix = installOf(program);
        return prefix == null ? new Located(program, source, null, launchEnvironment)
                : new Located(program, source, prefix, prefixEnvironment(prefix, launchEnvironment));
    }

    /**
     * The install prefix {@code program} is the Player of ({@code PREFIX/bin/player} with the
     * {@code PREFIX/env.sh} the install script writes), or null.
     */
    static @Nullable Path installOf(String program) {
        Path p;
        try {
            p = Path.of(program);
        } catch (java.nio.file.InvalidPathException e) {
            return null;
        }
        Path bin = p.getParent();
        if (!p.isAbsolute() || bin == null || bin.getParent() == null || !"bin".equals(String.valueOf(bin.getFileName()))) {
            return null;
        }
        Path prefix = bin.getParent();
        return Files.isRegularFile(prefix.resolve("env.sh")) && Files.isRegularFile(p) ? prefix : null;
    }

    private Map<String, String> prefixEnvironment(Path prefix, Map<String, String> launchEnvironment) {
        String lib = prefix.resolve("lib").toString();
        Map<String, String> env = new LinkedHashMap<>();
        env.put("PLAYERPATH", lib);
        env.put("STAGEPATH", prefix.resolve("share").resolve("stage") + ":" + prefix.resolve("lib").resolve("Stage-4.3"));
        env.putAll(launchEnvironment);
        @Nullable String existing = launchEnvironment.getOrDefault("LD_LIBRARY_PATH", processEnvironment.get("LD_LIBRARY_PATH"));
        env.put("LD_LIBRARY_PATH", existing == null || existing.isBlank() ? lib : lib + ":" + existing);
        return env;
    }

    private static boolean isSet(@Nullable String s) {
        return s != null && !s.isBlank();
    }
}
