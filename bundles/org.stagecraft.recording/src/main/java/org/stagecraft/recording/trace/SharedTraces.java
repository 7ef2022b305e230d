package org.stagecraft.recording.trace;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * Locates the recorded Player/Stage traffic in shared/traces beside the checkout. Missing traces
 * fail the tests: they are the ground truth, never optional.
 */
public final class SharedTraces {
    private SharedTraces() {
    }

    public static Path dir() {
        String prop = System.getProperty("stagecraft.traces");
        if (prop != null && Files.isDirectory(Path.of(prop))) {
            return Path.of(prop);
        }
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            Path candidate = p.resolve("shared").resolve("traces");
            if (Files.isDirectory(candidate)) {
                return candidate;
            }
            candidate = p.resolveSibling("shared").resolve("traces");
            if (Files.isDirectory(candidate)) {
                return candidate;
            }
        }
        throw new IllegalStateException("shared/traces not found (set -Dstagecraft.traces=DIR); tried from "
                + Path.of("").toAbsolutePath());
    }

    public static Path file(String name) {
        return dir().resolve(name);
    }

    /** Every *.trace.jsonl file. */
    public static List<Path> all() {
        try (Stream<Path> s = Files.list(dir())) {
            List<Path> traces = s.filter(p -> p.getFileName().toString().endsWith(".trace.jsonl")).sorted().toList();
            if (traces.isEmpty()) {
                throw new IllegalStateException("no *.trace.jsonl in " + dir());
            }
            return traces;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
