package org.stagecraft.demo.recorded;

import java.nio.file.Files;
import java.nio.file.Path;

/** The demo project as shipped in this bundle (the tests use what users get). */
final class DemoFiles {
    private DemoFiles() {
    }

    static Path project() {
        Path base = Path.of(System.getProperty("basedir", "")).toAbsolutePath();
        Path p = base.resolve("demo/pioneer-demo");
        if (!Files.isDirectory(p)) {
            throw new IllegalStateException("demo project not found at " + p);
        }
        return p;
    }

    static Path recording() {
        return project().resolve("recordings/pioneer-laser-sonar.gt.trace.jsonl");
    }

    static Path cfg() {
        return project().resolve("worlds/pioneer-laser-sonar.cfg");
    }
}
