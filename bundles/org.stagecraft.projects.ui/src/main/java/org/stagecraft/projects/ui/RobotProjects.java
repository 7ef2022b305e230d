package org.stagecraft.projects.ui;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IProjectDescription;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationType;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.jdt.annotation.Nullable;
import org.osgi.framework.Bundle;
import org.stagecraft.projects.ui.layout.ProgramTemplate;
import org.stagecraft.projects.ui.layout.PyDevProjectFile;
import org.stagecraft.projects.ui.layout.RobotProjectLayout;
import org.stagecraft.projects.ui.layout.TemplateSource;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.PythonClientPath;
import org.stagecraft.tools.ui.launch.RobotSessionTab;

/**
 * Robot Projects in the workspace: making a new one ({@link #create}), and making any project a
 * PyDev project that knows Stagecraft's Python client ({@link #configurePyDev}). PyDev is optional:
 * it is detected at run time and named by string ids only.
 */
public final class RobotProjects {
    public static final String BUNDLE = "org.stagecraft.projects.ui";
    /** PyDev's main bundle: installed or not decides whether projects get its nature. */
    public static final String PYDEV_BUNDLE = "org.python.pydev";
    public static final String PYDEV_NATURE = LaunchAttributes.PYDEV_NATURE;
    /** The name suffix of the launch configuration of the headless cfg. */
    public static final String HEADLESS_SUFFIX = " (headless)";

    private RobotProjects() {
    }

    /** What the New Robot Project wizard asks for. */
    public record Spec(String name, @Nullable URI location, ProgramTemplate program) {
        public Spec {
            if (name == null || name.isBlank()) {
                throw new IllegalArgumentException("a Robot Project needs a name");
            }
            if (program == null) {
                throw new IllegalArgumentException("a Robot Project needs a program template");
            }
        }
    }

    /** What {@link #create} made: the project, its program and cfgs, and the two Robot Session configurations. */
    public record Created(IProject project, IFile program, IFile windowedCfg, IFile headlessCfg,
            ILaunchConfiguration windowedLaunch, ILaunchConfiguration headlessLaunch) {
    }

    public static boolean pyDevInstalled() {
        return Platform.getBundle(PYDEV_BUNDLE) != null;
    }

    /** The templates shipped in this bundle (folder {@code templates/}, generated at build time). */
    public static TemplateSource bundleTemplates() {
        Bundle bundle = Platform.getBundle(BUNDLE);
        return path -> {
            URL entry = bundle.getEntry("templates/" + path);
            if (entry == null) {
                throw new IOException("template templates/" + path + " is missing from bundle " + BUNDLE
                        + " (the build generates templates/ from tests/traces/worlds and the Python examples)");
            }
            return entry.openStream();
        };
    }

    /**
     * Makes a Robot Project (see {@link RobotProjectLayout}): the project, its world and cfgs, the
     * program; a PyDev project if PyDev is installed; and a Robot Session launch configuration for
     * each cfg with the program, so Run As / Debug As &gt; Robot Session on a cfg runs it. Runs as one
     * workspace operation.
     */
    public static Created create(Spec spec, @Nullable IProgressMonitor monitor) throws CoreException {
        IWorkspace ws = ResourcesPlugin.getWorkspace();
        IStatus nameOk = ws.validateName(spec.name(), IResource.PROJECT);
        if (!nameOk.isOK()) {
            throw error("cannot name a project '" + spec.name() + "': " + nameOk.getMessage());
        }
        IProject project = ws.getRoot().getProject(spec.name());
        if (project.exists()) {
            throw error("a project named " + spec.name() + " exists already");
        }
        List<RobotProjectLayout.ProjectFile> files;
        try {
            files = RobotProjectLayout.files(spec.name(), spec.program(), bundleTemplates());
        } catch (IOException e) {
            throw error("cannot read the Robot Project templates: " + e.getMessage(), e);
        }
        ws.run(m -> {
            SubMonitor sub = SubMonitor.convert(m, "Creating Robot Project " + spec.name(), files.size() + 4);
            IProjectDescription d = ws.newProjectDescription(spec.name());
            d.setLocationURI(spec.location());
            project.create(d, sub.split(1));
            project.open(sub.split(1));
            for (RobotProjectLayout.ProjectFile f : files) {
                write(project.getFile(f.path()), f.content(), sub.split(1));
            }
            if (pyDevInstalled()) {
                configurePyDev(project, sub.split(2));
            }
        }, ws.getRoot(), IWorkspace.AVOID_UPDATE, monitor); // the root: configurePyDev adds a nature inside
        IFile program = project.getFile(RobotProjectLayout.programPath(spec.program()));
        IFile windowed = project.getFile(RobotProjectLayout.WINDOWED_CFG);
        IFile headless = project.getFile(RobotProjectLayout.HEADLESS_CFG);
        return new Created(project, program, windowed, headless, launchConfiguration(spec.name(), windowed, program),
                launchConfiguration(spec.name() + HEADLESS_SUFFIX, headless, program));
    }

    /**
     * Makes {@code project} a PyDev project set up for robot programs: its {@code .pydevproject}
     * gets a source folder (kept if it has one; else {@code src} if the project has that folder,
     * else the project folder) and Stagecraft's Python client folder as an external library, so
     * PyDev's code analysis and completion resolve {@code from stagecraft_player import ...}; then
     * the PyDev nature is added. Calling it again is harmless and updates the client folder after
     * the IDE moved it (an update). Without PyDev installed nothing changes. Runs as a workspace
     * operation with the workspace root's rule (adding a nature needs it): call it from a thread that
     * holds no scheduling rule, or the root's.
     *
     * @return whether the project is now a PyDev project (false: PyDev is not installed)
     * @throws CoreException if the project is not open, its {@code .pydevproject} cannot be read, or
     *             the workspace refuses the change
     */
    public static boolean configurePyDev(IProject project) throws CoreException {
        return configurePyDev(project, null);
    }

    /** {@link #configurePyDev(IProject)} with progress. */
    public static boolean configurePyDev(IProject project, @Nullable IProgressMonitor monitor) throws CoreException {
        if (!pyDevInstalled()) {
            return false;
        }
        if (!project.isOpen()) {
            throw error("project " + project.getName() + " is not open (or does not exist): cannot make it a PyDev project");
        }
        IWorkspace ws = ResourcesPlugin.getWorkspace();
        ws.run(m -> {
            SubMonitor sub = SubMonitor.convert(m, "Configuring " + project.getName() + " for PyDev", 2);
            Optional<String> client = PythonClientPath.folder();
            writePyDevSettings(project, client.isPresent() ? client.get() : null, sub.split(1));
            IProjectDescription d = project.getDescription();
            if (!Arrays.asList(d.getNatureIds()).contains(PYDEV_NATURE)) {
                List<String> natures = new ArrayList<>(Arrays.asList(d.getNatureIds()));
                natures.add(PYDEV_NATURE);
                d.setNatureIds(natures.toArray(String[]::new));
                project.setDescription(d, sub.split(1));
            }
        }, ws.getRoot(), IWorkspace.AVOID_UPDATE, monitor); // a change of natures takes the workspace root's rule
        return true;
    }

    /**
     * Writes Stagecraft's settings into the project's {@code .pydevproject} (made if missing, other
     * entries kept), without touching the project's natures; PyDev reads them when the nature is
     * added, or at once if it is there already. See {@link PyDevProjectFile#configure}.
     *
     * @param clientFolder the Python client's folder ({@link PythonClientPath#folder()}), or null
     * @return the file
     */
    public static IFile writePyDevSettings(IProject project, @Nullable String clientFolder, IProgressMonitor monitor)
            throws CoreException {
        IFile file = project.getFile(PyDevProjectFile.FILE_NAME);
        PyDevProjectFile settings;
        if (file.exists()) {
            try (InputStream in = file.getContents(true)) {
                settings = PyDevProjectFile.parse(new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw error(file.getFullPath() + ": " + e.getMessage(), e);
            }
        } else {
            settings = PyDevProjectFile.empty();
        }
        String source = project.getFolder(RobotProjectLayout.SOURCE_FOLDER).exists() ? RobotProjectLayout.SOURCE_FOLDER : "";
        if (clientFolder == null) {
            log(Status.warning(project.getName() + ": the Stagecraft Python client (" + PythonClientPath.BUNDLE
                    + ") is not installed, so PyDev will not resolve 'stagecraft_player' imports"));
        }
        if (settings.configure(source, clientFolder) || !file.exists()) {
            write(file, settings.toXml().getBytes(StandardCharsets.UTF_8), monitor);
        }
        return file;
    }

    /**
     * A Robot Session launch configuration for {@code cfg} with {@code program} (the Robot Session
     * tab's defaults otherwise), saved in the workspace and mapped to the cfg, so that Run As &gt;
     * Robot Session on the cfg finds it.
     */
    public static ILaunchConfiguration launchConfiguration(String name, IFile cfg, IFile program) throws CoreException {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationType type = lm.getLaunchConfigurationType(LaunchAttributes.TYPE);
        if (type == null) {
            throw error("the Robot Session launch type " + LaunchAttributes.TYPE + " is not installed (org.stagecraft.tools.ui)");
        }
        ILaunchConfigurationWorkingCopy wc = type.newInstance(null, lm.generateLaunchConfigurationName(name));
        new RobotSessionTab().setDefaults(wc);
        wc.setAttribute(LaunchAttributes.CFG, cfg.getFullPath().toString());
        wc.setAttribute(LaunchAttributes.PROGRAM, program.getFullPath().toString());
        wc.setMappedResources(new IResource[] {cfg});
        return wc.doSave();
    }

    private static void write(IFile file, byte[] content, IProgressMonitor monitor) throws CoreException {
        mkdirs(file.getParent(), monitor);
        if (file.exists()) {
            file.setContents(new ByteArrayInputStream(content), IResource.KEEP_HISTORY, monitor);
        } else {
            file.create(new ByteArrayInputStream(content), IResource.NONE, monitor);
        }
    }

    private static void mkdirs(IContainer c, IProgressMonitor monitor) throws CoreException {
        if (c instanceof IFolder folder && !folder.exists()) {
            mkdirs(folder.getParent(), monitor);
            folder.create(IResource.NONE, true, monitor);
        }
    }

    static void log(IStatus status) {
        ILog.of(Platform.getBundle(BUNDLE)).log(status);
    }

    static CoreException error(String message) {
        return new CoreException(Status.error(message));
    }

    static CoreException error(String message, Throwable cause) {
        return new CoreException(Status.error(message, cause));
    }
}
