package org.stagecraft.tools.session;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.jdt.annotation.NonNullByDefault;

/**
 * A session's private directory for the rewritten cfg files, under a common root
 * ({@code java.io.tmpdir/stagecraft-sessions} unless told otherwise). Its name starts with the
 * owning JVM's process id, so the next session can tell the leftovers of a crashed IDE (owner no
 * longer running) from those of another running IDE, and removes only the former.
 */
public final class ScratchDirectory implements AutoCloseable {
    private static final AtomicInteger COUNTER = new AtomicInteger();
    private final Path dir;

    private ScratchDirectory(Path dir) {
        this.dir = dir;
    }

    public static Path defaultRoot() {
        return Path.of(System.getProperty("java.io.tmpdir"), "stagecraft-sessions");
    }

    /** Removes stale directories under {@code root}, then creates a new one. */
    public static ScratchDirectory create(Path root) throws IOException {
        Files.createDirectories(root);
        removeStale(root);
        long pid = ProcessHandle.current().pid();
        Path dir = Files.createTempDirectory(root, pid + "-" + COUNTER.incrementAndGet() + "-");
        return new ScratchDirectory(dir);
    }

    /** Deletes every directory under {@code root} whose owner process no longer runs; returns them. */
    public static List<Path> removeStale(Path root) throws IOException {
        List<Path> removed = new ArrayList<>();
        if (!Files.isDirectory(root)) {
            return removed;
        }
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(root)) {
            for (Path p : ds) {
                String name = p.getFileName().toString();
                int dash = name.indexOf('-');
                long owner;
                try {
                    owner = Long.parseLong(dash > 0 ? name.substring(0, dash) : name);
                } catch (NumberFormatException e) {
                    continue; // not ours
                }
                Optional<ProcessHandle> h = ProcessHandle.of(owner);
                if (h.isEmpty() || !h.get().isAlive()) {
                    deleteTree(p);
                    removed.add(p);
                }
            }
        }
        return removed;
    }

    public Path path() {
        return dir;
    }

    @Override
    public void close() throws IOException {
        deleteTree(dir);
    }

    static void deleteTree(Path p) throws IOException {
        if (!Files.exists(p)) {
            return;
        }
        Files.walkFileTree(p, new SimpleFileVisitor<>() {
            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                Files.deleteIfExists(file);
                return FileVisitResult.CONTINUE;
            }

            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public FileVisitResult postVisitDirectory(Path d, IOException exc) throws IOException {
                Files.deleteIfExists(d);
                return FileVisitResult.CONTINUE;
            }
        });
    }
}
