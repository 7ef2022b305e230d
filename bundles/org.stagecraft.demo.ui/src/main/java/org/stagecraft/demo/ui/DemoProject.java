package org.stagecraft.demo.ui;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Enumeration;
import java.util.List;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IWorkspaceRunnable;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.osgi.framework.Bundle;

/**
 * The demo project in the workspace: the files shipped in {@code org.stagecraft.demo}'s
 * {@code demo/pioneer-demo/} (the cfg and world, the recording), created on the first run and put back
 * to the shipped content on later runs. Files the user or the sessions added (spy logs, programs) stay.
 */
final class DemoProject {
    static final String NAME = "pioneer-demo";
    static final String CFG = "worlds/pioneer-laser-sonar.cfg";
    static final String RECORDING = "recordings/pioneer-laser-sonar.gt.trace.jsonl";
    static final String LOG_FOLDER = "spy-logs";
    private static final String SOURCE_BUNDLE = "org.stagecraft.demo";
    private static final String SOURCE = "demo/pioneer-demo/";

    private DemoProject() {
    }

    static IProject install(IProgressMonitor monitor) throws CoreException {
        IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject(NAME);
        IWorkspaceRunnable op = m -> {
            if (!project.exists()) {
                project.create(m);
            }
            project.open(m);
            project.refreshLocal(IResource.DEPTH_INFINITE, m);
            for (URL entry : shippedFiles()) {
                copy(entry, project, m);
            }
            IFolder logs = project.getFolder(LOG_FOLDER);
            if (!logs.exists()) {
                logs.create(true, true, m);
            }
        };
        ResourcesPlugin.getWorkspace().run(op, monitor);
        return project;
    }

    private static List<URL> shippedFiles() throws CoreException {
        Bundle bundle = Platform.getBundle(SOURCE_BUNDLE);
        Enumeration<URL> entries = bundle == null ? null : bundle.findEntries(SOURCE, "*", true);
        if (entries == null) {
            throw new CoreException(Status.error("the demo project is missing from the installation ("
                    + SOURCE_BUNDLE + "/" + SOURCE + ")"));
        }
        List<URL> files = new ArrayList<>();
        for (URL u : Collections.list(entries)) {
            if (!u.getPath().endsWith("/")) {
                files.add(u);
            }
        }
        return files;
    }

    private static void copy(URL entry, IProject project, IProgressMonitor m) throws CoreException {
        String path = entry.getPath();
        String relative = path.substring(path.indexOf(SOURCE) + SOURCE.length());
        IFile file = project.getFile(relative);
        byte[] shipped;
        try (InputStream in = entry.openStream()) {
            shipped = in.readAllBytes();
        } catch (IOException e) {
            throw new CoreException(Status.error("cannot read " + path + " from the installation", e));
        }
        if (file.exists()) {
            try (InputStream in = file.getContents(true)) {
                if (Arrays.equals(in.readAllBytes(), shipped)) {
                    return;
                }
            } catch (IOException e) {
                // unreadable: replaced below
            }
            file.setContents(new ByteArrayInputStream(shipped), IResource.FORCE, m);
            return;
        }
        createParents(file.getParent(), m);
        file.create(new ByteArrayInputStream(shipped), IResource.FORCE, m);
    }

    private static void createParents(IContainer c, IProgressMonitor m) throws CoreException {
        if (c instanceof IFolder f && !f.exists()) {
            createParents(f.getParent(), m);
            f.create(true, true, m);
        }
    }
}
