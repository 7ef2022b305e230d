package org.stagecraft.tools.session;

import java.nio.file.Files;
import java.nio.file.Path;

/** The Player cfg/world files and traces of the checkout's corpus, tests/traces (never optional). */
public final class Worlds {
    private Worlds() {
    }

    public static Path traces() {
        String prop = System.getProperty("stagecraft.traces");
        if (prop != null && Files.isDirectory(Path.of(prop))) {
            return Path.of(prop).toAbsolutePath();
        }
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            Path candidate = p.resolve("tests").resolve("traces");
            if (Files.isRegularFile(candidate.resolve("README.md"))) {
                return candidate;
            }
        }
        throw new IllegalStateException("tests/traces not found (set -Dstagecraft.traces=DIR)");
    }

    public static Path file(String name) {
        return traces().resolve("worlds").resolve(name);
    }

    /** The stand-in for Player that the plug-in tests use too. */
    public static Path standIn() {
        Path base = Path.of(System.getProperty("basedir", "")).toAbsolutePath();
        Path script = base.resolve("../../tests/org.stagecraft.tools.tests/standin/player-standin.py").normalize();
        if (!Files.isRegularFile(script)) {
            throw new IllegalStateException("stand-in Player not found at " + script);
        }
        return script;
    }
}
