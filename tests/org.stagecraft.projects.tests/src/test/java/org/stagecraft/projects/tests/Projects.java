package org.stagecraft.projects.tests;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchManager;
import org.stagecraft.tools.ui.launch.LaunchAttributes;

/** What the tests compare with (the corpus, the client's examples) and clean up (projects, Robot Session configurations). */
final class Projects {
    private Projects() {
    }

    static Path worlds() {
        String prop = System.getProperty("stagecraft.traces");
        if (prop == null || !Files.isDirectory(Path.of(prop, "worlds"))) {
            throw new IllegalStateException("the trace corpus (tests/traces) not found: -Dstagecraft.traces=" + prop);
        }
        return Path.of(prop, "worlds");
    }

    /** A file of the bundle org.stagecraft.python (python/examples/...). */
    static byte[] pythonBundleFile(String path) throws IOException {
        URL url = Platform.getBundle("org.stagecraft.python").getEntry(path);
        if (url == null) {
            throw new IOException("org.stagecraft.python has no " + path);
        }
        try (InputStream in = url.openStream()) {
            return in.readAllBytes();
        }
    }

    static byte[] contents(IFile f) throws CoreException, IOException {
        try (InputStream in = f.getContents(true)) {
            return in.readAllBytes();
        }
    }

    static List<ILaunchConfiguration> robotSessions() throws CoreException {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        return List.of(lm.getLaunchConfigurations(lm.getLaunchConfigurationType(LaunchAttributes.TYPE)));
    }

    /**
     * Deletes every project and every Robot Session configuration.
     */
    static void clean() throws CoreException {
        for (ILaunchConfiguration c : new ArrayList<>(robotSessions())) {
            c.delete();
        }
        for (IProject p : ResourcesPlugin.getWorkspace().getRoot().getProjects()) {
            p.delete(true, true, null);
        }
    }
}
