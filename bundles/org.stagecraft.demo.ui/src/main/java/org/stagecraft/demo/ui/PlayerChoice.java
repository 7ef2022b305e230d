package org.stagecraft.demo.ui;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Which "Player" the demo session runs: a real Player/Stage when one is installed (or named), the
 * recorded one otherwise.
 *
 * @param program  what the Robot Session starts as Player
 * @param recorded whether that is the recorded Player (then the recording is given in its environment)
 */
record PlayerChoice(String program, boolean recorded) {

    static PlayerChoice choose(String option, Path recordedLauncher) {
        if (DemoOptions.RECORDED.equals(option)) {
            return new PlayerChoice(recordedLauncher.toString(), true);
        }
        if (DemoOptions.AUTO.equals(option)) {
            Path real = onPath("player");
            return real != null ? new PlayerChoice(real.toString(), false) : new PlayerChoice(recordedLauncher.toString(), true);
        }
        return new PlayerChoice(option, false);
    }

    static Path onPath(String name) {
        String path = System.getenv("PATH");
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
