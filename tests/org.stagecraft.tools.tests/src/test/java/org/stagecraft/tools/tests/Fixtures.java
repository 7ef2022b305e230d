package org.stagecraft.tools.tests;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.FileLocator;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.DebugException;
import org.eclipse.debug.core.ILaunch;
import org.stagecraft.tests.support.Await;

/** Workspace projects with the corpus's Player worlds, the stand-in Player, the recorded traces. */
final class Fixtures {
    private Fixtures() {
    }

    static Path traces() {
        String prop = System.getProperty("stagecraft.traces");
        if (prop == null || !Files.isDirectory(Path.of(prop))) {
            throw new IllegalStateException("the trace corpus (tests/traces) not found: -Dstagecraft.traces=" + prop);
        }
        return Path.of(prop).toAbsolutePath().normalize();
    }

    /** The stand-in Player, copied out of the test bundle as an executable file. */
    static Path standIn(Path dir) throws IOException {
        URL url = FileLocator.toFileURL(Platform.getBundle("org.stagecraft.tools.tests").getEntry("standin/player-standin.py"));
        Path target = dir.resolve("player-standin.py");
        try (InputStream in = url.openStream()) {
            Files.copy(in, target);
        }
        Files.setPosixFilePermissions(target, PosixFilePermissions.fromString("rwxr-xr-x"));
        return target;
    }

    /** A new project holding a copy of tests/traces/worlds in its folder "worlds". */
    static IProject projectWithWorlds(String name) throws CoreException, IOException {
        IProject p = ResourcesPlugin.getWorkspace().getRoot().getProject(name);
        if (p.exists()) {
            p.delete(true, true, new NullProgressMonitor());
        }
        p.create(new NullProgressMonitor());
        p.open(new NullProgressMonitor());
        Path from = traces().resolve("worlds");
        Path to = p.getLocation().toPath().resolve("worlds");
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path dest = to.resolve(from.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(dest);
                } else {
                    Files.copy(f, dest);
                }
            }
        }
        p.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());
        return p;
    }

    static IFile write(IProject p, String path, String text) throws CoreException, IOException {
        Path file = p.getLocation().toPath().resolve(path);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        p.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());
        return p.getFile(path);
    }

    /** Ends the launches and waits until each has: a session stops in the background, and the next test must not see it running. */
    static void terminateAll(List<ILaunch> launches, Duration wait) throws DebugException {
        for (ILaunch l : launches) {
            if (!l.isTerminated()) {
                l.terminate();
            }
            Await.until("the launch is terminated", wait, l::isTerminated);
        }
    }
}
