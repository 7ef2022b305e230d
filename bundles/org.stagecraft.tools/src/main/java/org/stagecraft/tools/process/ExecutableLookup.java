package org.stagecraft.tools.process;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;

/** Finds a program by name on a PATH, as a shell's exec would. */
public final class ExecutableLookup {
    private ExecutableLookup() {
    }

    /**
     * The first executable file {@code name} in the directories of PATH ({@code environment}'s PATH if
     * it sets one, else this process's).
     */
    public static Optional<Path> onPath(String name, Map<String, String> environment) {
        String path = environment.getOrDefault("PATH", System.getenv("PATH"));
        return in(name, path);
    }

    /** The first executable file {@code name} in the {@code :}-separated directories of {@code path}. */
    public static Optional<Path> in(String name, String path) {
        if (path == null || name.isEmpty() || name.contains("/")) {
            return Optional.empty();
        }
        for (String dir : path.split(File.pathSeparator)) {
            Path candidate = Path.of(dir.isEmpty() ? "." : dir).resolve(name);
            if (Files.isRegularFile(candidate) && Files.isExecutable(candidate)) {
                return Optional.of(candidate.toAbsolutePath());
            }
        }
        return Optional.empty();
    }
}
