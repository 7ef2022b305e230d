package org.stagecraft.projects.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.stagecraft.projects.ui.RobotProjects;
import org.stagecraft.projects.ui.RobotSessionProjects;
import org.stagecraft.projects.ui.layout.ProgramTemplate;
import org.stagecraft.projects.ui.layout.PyDevProjectFile;
import org.stagecraft.projects.ui.layout.RobotProjectLayout;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.PythonClientPath;
import org.stagecraft.tools.ui.launch.RobotSessionShortcut;

/** The wizard's operation, {@link RobotProjects#create}, in a workbench without PyDev. */
class NewRobotProjectTest {

    @BeforeEach
    @AfterEach
    void clean() throws CoreException {
        Projects.clean();
    }

    /** These run without PyDev; the PyDev tier (PyDevRobotProjectTest) runs the wizard with it. */
    @Test
    void theseTestsRunWithoutPyDev() {
        assertEquals(null, Platform.getBundle("org.python.pydev"), "PyDev in the test runtime");
        assertFalse(RobotProjects.pyDevInstalled());
    }

    @ParameterizedTest
    @EnumSource(ProgramTemplate.class)
    void createsWorldCfgsAndProgram(ProgramTemplate template) throws Exception {
        RobotProjects.Created c = RobotProjects.create(new RobotProjects.Spec("Bot " + template, null, template), null);
        IProject p = c.project();
        assertTrue(p.isOpen());
        assertEquals(ResourcesPlugin.getWorkspace().getRoot().getLocation().append(p.getName()), p.getLocation(),
                "default location");
        for (String path : RobotProjectLayout.WORLD_FILES) {
            IFile f = p.getFile(path);
            assertTrue(f.exists(), path);
            Path source = Projects.worlds().resolve(path.substring("worlds/".length()));
            assertArrayEquals(Files.readAllBytes(source), Projects.contents(f), path + " is not the corpus's " + source);
        }
        assertEquals(p.getFile("src/" + template.fileName()), c.program());
        byte[] program = Projects.contents(c.program());
        if (template.templatePath() != null) {
            assertArrayEquals(Projects.pythonBundleFile("python/" + template.templatePath()), program, template.name());
        } else {
            String text = new String(program, StandardCharsets.UTF_8);
            assertTrue(text.contains("from stagecraft_player import Client") && text.contains("Bot EMPTY"), text);
        }
        assertTrue(new String(Projects.contents(c.windowedCfg()), StandardCharsets.UTF_8).contains("usegui 1"));
        assertTrue(new String(Projects.contents(c.headlessCfg()), StandardCharsets.UTF_8).contains("usegui 0"));
    }

    @Test
    void plainProjectWithoutPyDev() throws Exception {
        IProject p = RobotProjects.create(new RobotProjects.Spec("Plain", null, ProgramTemplate.LASER_SENTINEL), null).project();
        assertEquals(List.of(), List.of(p.getDescription().getNatureIds()), "no natures without PyDev");
        assertFalse(p.getFile(PyDevProjectFile.FILE_NAME).exists(), ".pydevproject only with PyDev");
        assertFalse(RobotProjects.configurePyDev(p), "configurePyDev does nothing without PyDev");
        assertFalse(p.hasNature(RobotProjects.PYDEV_NATURE));
        assertFalse(p.getFile(PyDevProjectFile.FILE_NAME).exists());
    }

    @Test
    void robotSessionConfigurationsForBothCfgsThatRunAsReuses() throws Exception {
        RobotProjects.Created c = RobotProjects.create(new RobotProjects.Spec("Sentinel", null, ProgramTemplate.SUNDAY_STROLL), null);
        assertEquals(2, Projects.robotSessions().size(), "one configuration per cfg: " + Projects.robotSessions());
        check(c.windowedLaunch(), "Sentinel", "/Sentinel/worlds/pioneer-laser-sonar.cfg", c.windowedCfg());
        check(c.headlessLaunch(), "Sentinel (headless)", "/Sentinel/worlds/pioneer-laser-sonar-headless.cfg", c.headlessCfg());
        // Run As > Robot Session on a cfg finds these rather than making new ones without the program
        assertEquals(c.windowedLaunch(), RobotSessionShortcut.configurationFor(c.windowedCfg()));
        assertEquals(c.headlessLaunch(), RobotSessionShortcut.configurationFor(c.headlessCfg()));
        assertEquals(2, Projects.robotSessions().size());
    }

    /** What {@link RobotSessionProjects} would make a robot project: the project of a Robot Session's program. */
    @Test
    void theProjectOfARobotSessionsProgramIsFoundAndAPlainOneIsNotConfigured() throws Exception {
        RobotProjects.Created c = RobotProjects.create(new RobotProjects.Spec("Launched", null, ProgramTemplate.LASER_SENTINEL), null);
        assertEquals(c.project(), RobotSessionProjects.robotProject(c.windowedLaunch()));
        ILaunchConfigurationWorkingCopy noProgram = c.headlessLaunch().getWorkingCopy();
        noProgram.setAttribute(LaunchAttributes.PROGRAM, "");
        assertEquals(c.project(), RobotSessionProjects.robotProject(noProgram), "the cfg's project when no program is set");
        noProgram.setAttribute(LaunchAttributes.CFG, "/elsewhere/robot.cfg");
        assertEquals(null, RobotSessionProjects.robotProject(noProgram), "nothing of the workspace: left alone");
        assertEquals(null, RobotSessionProjects.robotProject(null), "a launch without a configuration");
        assertEquals(RobotProjects.pyDevInstalled(), RobotSessionProjects.configured(c.project()),
                "configured exactly when the wizard could make it a PyDev project");
    }

    private static void check(ILaunchConfiguration l, String name, String cfg, IFile cfgFile) throws CoreException {
        assertEquals(name, l.getName());
        assertEquals(LaunchAttributes.TYPE, l.getType().getIdentifier());
        assertTrue(l.exists(), "saved");
        assertEquals(cfg, l.getAttribute(LaunchAttributes.CFG, ""));
        assertEquals("/Sentinel/src/sunday_stroll.py", l.getAttribute(LaunchAttributes.PROGRAM, ""));
        assertEquals(LaunchAttributes.DEFAULT_LOG_FOLDER, l.getAttribute(LaunchAttributes.LOG_FOLDER, ""));
        assertEquals(6665, l.getAttribute(LaunchAttributes.DEFAULT_PORT, 0));
        assertEquals(List.of(cfgFile), List.of(l.getMappedResources()));
        assertTrue(l.supportsMode("debug") && l.supportsMode("run"));
    }

    @Test
    void refusesAnExistingProjectAndBadNames() throws Exception {
        RobotProjects.create(new RobotProjects.Spec("Twice", null, ProgramTemplate.EMPTY), null);
        CoreException e = assertThrows(CoreException.class,
                () -> RobotProjects.create(new RobotProjects.Spec("Twice", null, ProgramTemplate.EMPTY), null));
        assertTrue(e.getMessage().contains("Twice") && e.getMessage().contains("exists already"), e.getMessage());
        CoreException bad = assertThrows(CoreException.class,
                () -> RobotProjects.create(new RobotProjects.Spec("a/b", null, ProgramTemplate.EMPTY), null));
        assertTrue(bad.getMessage().startsWith("cannot name a project 'a/b': "), bad.getMessage());
        assertFalse(ResourcesPlugin.getWorkspace().getRoot().getProject("a").exists());
        IllegalArgumentException blank = assertThrows(IllegalArgumentException.class,
                () -> new RobotProjects.Spec(" ", null, ProgramTemplate.EMPTY));
        assertTrue(blank.getMessage().contains("name"), blank.getMessage());
    }

    @Test
    void elsewhereOnDisk(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path location = dir.resolve("robots").resolve("far");
        IProject p = RobotProjects.create(new RobotProjects.Spec("Far", location.toUri(), ProgramTemplate.EMPTY), null).project();
        assertTrue(Files.isRegularFile(location.resolve("src/robot.py")), "program in the chosen folder");
        assertTrue(Files.isRegularFile(location.resolve(RobotProjectLayout.WINDOWED_CFG)));
        assertEquals(location.toRealPath(), p.getLocation().toPath().toRealPath());
    }

    /** What configurePyDev writes before it adds PyDev's nature: testable without PyDev. */
    @Test
    void pyDevSettingsNameSourceFolderAndTheClientWhereStagecraftPlayerIs() throws Exception {
        IProject p = ResourcesPlugin.getWorkspace().getRoot().getProject("Analysed");
        p.create(null);
        p.open(null);
        p.getFolder("src").create(true, true, null);
        String client = PythonClientPath.folder().orElseThrow(() -> new AssertionError("org.stagecraft.python is in the test runtime"));
        IFile file = RobotProjects.writePyDevSettings(p, client, null);
        assertEquals(p.getFile(".pydevproject"), file);
        PyDevProjectFile settings = PyDevProjectFile.parse(new String(Projects.contents(file), StandardCharsets.UTF_8));
        assertEquals(List.of("/${PROJECT_DIR_NAME}/src"), settings.paths(PyDevProjectFile.SOURCE_PATH));
        assertEquals(List.of(client), settings.paths(PyDevProjectFile.EXTERNAL_SOURCE_PATH));
        assertTrue(Files.isRegularFile(Path.of(client, "stagecraft_player", "__init__.py")),
                "the library folder holds the package the programs import: " + client);
        long stamp = file.getModificationStamp();
        RobotProjects.writePyDevSettings(p, client, null);
        assertEquals(stamp, file.getModificationStamp(), "nothing to change: the file is left alone");
        assertFalse(p.hasNature(RobotProjects.PYDEV_NATURE), "the settings alone add no nature");
        assertEquals(IResource.FILE, file.getType());
    }
}
