package org.stagecraft.demo;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

import org.eclipse.jdt.annotation.Nullable;

/**
 * Which "Player" the demo session runs: a real Player/Stage when one is installed (or named), the
 * recorded one otherwise.
 *
 * @param program  what the Robot Session starts as Player
 * @param recorded whether that is the recorded Player (then the recording is given in its environment)
 */
public record PlayerChoice(String program, boolean recorded) {
    /** Use a real {@code player} found on the PATH, else the recorded one. */
    public static final String AUTO = "auto";
    /** Use the recorded Player even if a real one is installed. */
    public static final String RECORDED = "recorded";

    /**
     * @param option           {@link #AUTO}, {@link #RECORDED}, or the Player program to use
     * @param recordedLauncher the recorded Player's launcher
     * @param path             the PATH to search (as in the environment; may be null)
     */
    public static PlayerChoice choose(String option, Path recordedLauncher, String path) {
        if (RECORDED.equals(option)) {
            return new PlayerChoice(recordedLauncher.toString(), true);
        }
        if (AUTO.equals(option)) {
            Path real = onPath("player", path);
            return real != null ? new PlayerChoice(real.toString(), false) : new PlayerChoice(recordedLauncher.toString(), true);
        }
        return new PlayerChoice(option, false);
    }

    static @Nullable Path onPath(String name, String path) {
        if (path == null) {
            return null;
        }
        for (String dir : path.split(File.pathSeparator)) {
            if (dir.isBlank()) {
                continue;
            }
            Path p = Path.of(dir, name);
            if (Files.isRegularFile(p) && Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }
}
