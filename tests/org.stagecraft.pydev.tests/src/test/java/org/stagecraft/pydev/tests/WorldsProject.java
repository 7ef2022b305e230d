package org.stagecraft.pydev.tests;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.stream.Stream;

import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.python.pydev.core.IPythonNature;
import org.python.pydev.plugin.nature.PythonNature;

/** The PyDev project both tiers run their programs from: a copy of the corpus's worlds, made by PyDev's own API. */
final class WorldsProject {
    private WorldsProject() {
    }

    /** The recorded corpus, tests/traces (the build passes it as -Dstagecraft.traces). */
    static Path traces() {
        String prop = System.getProperty("stagecraft.traces");
        if (prop == null || !Files.isDirectory(Path.of(prop))) {
            throw new IllegalStateException("the trace corpus (tests/traces) not found: -Dstagecraft.traces=" + prop);
        }
        return Path.of(prop).toAbsolutePath().normalize();
    }

    /**
     * A new PyDev project (source folder: the project) holding a copy of tests/traces/worlds and the
     * folders {@code extraFolders}.
     *
     * @param externalLibrary a folder for PyDev's external libraries, or null for none
     */
    static IProject create(String name, Path externalLibrary, String... extraFolders) throws Exception {
        IProject p = ResourcesPlugin.getWorkspace().getRoot().getProject(name);
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
        for (String folder : extraFolders) {
            Files.createDirectories(p.getLocation().toPath().resolve(folder));
        }
        p.refreshLocal(IResource.DEPTH_INFINITE, new NullProgressMonitor());
        PythonNature.addNature(p, new NullProgressMonitor(), IPythonNature.Versions.PYTHON_VERSION_LATEST, "/" + name,
                externalLibrary == null ? null : externalLibrary.toString(), IPythonNature.DEFAULT_INTERPRETER, null);
        // PyDev restores a new project's modules in the background and, asked for the project's
        // PYTHONPATH before that is done, waits one second and then launches nothing (a
        // NullPointerException inside PythonRunnerConfig, seen on a loaded machine). A user creates
        // a project long before running it; the tests launch at once, so they wait as long as PyDev needs.
        PythonNature nature = PythonNature.getPythonNature(p);
        Await.until("PyDev has restored the modules of " + name, Duration.ofSeconds(60),
                () -> nature != null && nature.isOkToUse(), () -> "; nature: " + nature);
        return p;
    }
}
