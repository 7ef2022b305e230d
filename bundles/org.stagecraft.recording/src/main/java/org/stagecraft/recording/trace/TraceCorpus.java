package org.stagecraft.recording.trace;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * Locates the recorded Player/Stage corpus, the project's own test data in {@code tests/traces} of the
 * checkout. {@code -Dstagecraft.traces=DIR} or {@code STAGECRAFT_TRACES=DIR} point elsewhere (e.g. at
 * held-back recordings of the same format). Missing traces fail the tests: they are the ground truth,
 * never optional.
 */
public final class TraceCorpus {
    /** The corpus inside a checkout, relative to its root. */
    public static final String IN_CHECKOUT = "tests/traces";

    private TraceCorpus() {
    }

    public static Path dir() {
        String prop = System.getProperty("stagecraft.traces");
        if (prop == null || prop.isBlank()) {
            prop = System.getenv("STAGECRAFT_TRACES");
        }
        if (prop != null && !prop.isBlank()) {
            Path given = Path.of(prop);
            if (!Files.isDirectory(given)) {
                throw new IllegalStateException("the trace corpus " + given
                        + " (from -Dstagecraft.traces or STAGECRAFT_TRACES) is not a folder");
            }
            return given;
        }
        // walk up from the working folder (a module of the checkout) to the checkout's tests/traces
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            Path candidate = p.resolve(IN_CHECKOUT);
            if (Files.isRegularFile(candidate.resolve("README.md"))) {
                return candidate;
            }
        }
        throw new IllegalStateException(IN_CHECKOUT + " not found above " + Path.of("").toAbsolutePath()
                + " (set -Dstagecraft.traces=DIR or STAGECRAFT_TRACES=DIR)");
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
