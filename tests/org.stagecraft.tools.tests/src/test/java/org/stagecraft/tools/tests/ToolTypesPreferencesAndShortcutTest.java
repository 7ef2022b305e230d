package org.stagecraft.tools.tests;

import org.eclipse.core.expressions.EvaluationContext;
import org.eclipse.core.expressions.EvaluationResult;
import org.eclipse.core.expressions.Expression;
import org.eclipse.core.expressions.ExpressionConverter;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IConfigurationElement;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.Platform;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.junit.jupiter.api.Test;
import org.stagecraft.tools.process.Readiness;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.process.ToolSpec;
import org.stagecraft.tools.types.GenericToolType;
import org.stagecraft.tools.types.ToolDefinition;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionShortcut;
import org.stagecraft.tools.ui.prefs.ToolPreferences;
import org.stagecraft.tools.ui.registry.ToolTypeExtensionRegistry;

/** The tool types extension point, user tools as preferences, and the .cfg launch shortcut. */
class ToolTypesPreferencesAndShortcutTest {

    @Test
    void contributedTypesLoadAndBrokenOnesAreReportedAndSkipped() {
        List<IStatus> problems = new ArrayList<>();
        List<ToolTypeExtensionRegistry.Contribution> types = ToolTypeExtensionRegistry.load(Platform.getExtensionRegistry(),
                problems::add);
        List<String> ids = types.stream().map(ToolTypeExtensionRegistry.Contribution::id).toList();
        assertTrue(ids.contains(GenericToolType.ID), ids.toString());
        assertTrue(ids.contains("org.stagecraft.tools.tests.echo"), ids.toString());
        assertEquals(1, ids.stream().filter(GenericToolType.ID::equals).count(), "the duplicate id is skipped");
        String all = problems.stream().map(IStatus::getMessage).toList().toString();
        assertEquals(3, problems.size(), all);
        assertTrue(all.contains("plug-in org.stagecraft.tools.tests, extension org.stagecraft.tools.ui.toolTypes, element "
                + "<toolType> id 'org.stagecraft.tools.tests.missing'"), all);
        assertTrue(all.contains("does not implement org.stagecraft.tools.types.ToolType"), all);
        assertTrue(all.contains("another tool type already has id 'org.stagecraft.tools.generic'"), all);

        ToolSpec echo = types.stream().filter(t -> t.id().equals("org.stagecraft.tools.tests.echo")).findFirst().orElseThrow()
                .type().toSpec(ToolDefinition.of("e", "hello", ""));
        assertEquals(Readiness.line("^echo-tool ").describe(), echo.readiness().describe());
    }

    @Test
    void userToolsAreStoredAsPreferencesInOrder() throws Exception {
        List<ToolDefinition> tools = List.of(
                new ToolDefinition("stage", null, "stage", "--gui \"my world.world\"", "/tmp", Map.of("A", "1", "B", "x=y"),
                        "port:127.0.0.1:6670", "on-failure:2", 15, true),
                new ToolDefinition("logger", null, "logger.sh", "", "", Map.of(), "line:ready", "never", 30, false));
        try {
            ToolPreferences.setTools(tools);
            assertEquals(tools, ToolPreferences.tools());
            assertTrue(Platform.getPreferencesService().getRootNode().node("instance/" + ToolPreferences.NODE + "/tools/0")
                    .get("command", "").equals("stage"), "stored in the instance scope, like other Eclipse preferences");
            ToolSpec spec = new GenericToolType().toSpec(ToolPreferences.tools().get(0));
            assertEquals(List.of("stage", "--gui", "my world.world"), spec.command());
            assertEquals(RestartPolicy.onFailure(2), spec.restart());
            assertEquals(new Readiness.PortsOpen("127.0.0.1", List.of(6670)), spec.readiness());
        } finally {
            ToolPreferences.setTools(List.of());
        }
        assertEquals("player", ToolPreferences.get(ToolPreferences.PLAYER), "default: player on PATH");
        assertEquals("python3", ToolPreferences.get(ToolPreferences.PYTHON));
    }

    @Test
    void aBadToolDefinitionIsNamed() {
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> new GenericToolType().toSpec(new ToolDefinition("sim", null, "stage", "", "", Map.of(), "port:abc",
                        "never", 10, true)));
        assertTrue(e.getMessage().startsWith("tool 'sim': readiness 'port:abc'"), e.getMessage());
    }

    @Test
    void theShortcutMakesOneConfigurationPerCfgWithTheProgramBesideIt() throws Exception {
        IProject p = Fixtures.projectWithWorlds("shortcut-" + System.nanoTime());
        try {
            Fixtures.write(p, "worlds/avoid.py", "print('hi')\n");
            IFile cfg = p.getFile("worlds/six-robots.cfg");
            ILaunchConfiguration c = RobotSessionShortcut.configurationFor(cfg);
            assertEquals(cfg.getFullPath().toString(), c.getAttribute(LaunchAttributes.CFG, ""));
            assertEquals(p.getFile("worlds/avoid.py").getFullPath().toString(), c.getAttribute(LaunchAttributes.PROGRAM, ""));
            assertEquals(LaunchAttributes.DEFAULT_LOG_FOLDER, c.getAttribute(LaunchAttributes.LOG_FOLDER, ""));
            assertEquals(c, RobotSessionShortcut.configurationFor(cfg), "the same configuration the next time");
            c.delete();
        } finally {
            p.delete(true, true, new NullProgressMonitor());
        }
    }

    @Test
    void runAsRobotSessionAlsoOnTheProgramFindingItsCfgBesideItOrInTheProject() throws Exception {
        IProject p = Fixtures.projectWithWorlds("shortcut-py-" + System.nanoTime());
        try {
            // the shortcut is offered on a .py file (and still on a .cfg), not on others
            IFile solo = Fixtures.write(p, "solo/robot.py", "print('hi')\n");
            IFile soloCfg = Fixtures.write(p, "solo/robot.cfg", "driver ( name \"stage\" provides [ \"simulation:0\" ] )\n");
            assertTrue(shortcutEnabledOn(solo), "Run As > Robot Session on a .py file");
            assertTrue(shortcutEnabledOn(soloCfg), "Run As > Robot Session on a .cfg file");
            assertFalse(shortcutEnabledOn(p.getFile("worlds/pioneer-laser-sonar.world")), "not on a .world file");

            ILaunchConfiguration c = RobotSessionShortcut.configurationForProgram(solo);
            assertEquals(solo.getFullPath().toString(), c.getAttribute(LaunchAttributes.PROGRAM, ""));
            assertEquals(soloCfg.getFullPath().toString(), c.getAttribute(LaunchAttributes.CFG, ""), "the only cfg beside it");
            assertEquals(c, RobotSessionShortcut.configurationForProgram(solo), "the same configuration the next time");
            c.delete();

            // beside several cfgs and in a project with several: no cfg chosen (the launch dialog asks)
            IFile among = Fixtures.write(p, "worlds/avoid.py", "print('hi')\n");
            ILaunchConfiguration d = RobotSessionShortcut.configurationForProgram(among);
            assertEquals("", d.getAttribute(LaunchAttributes.CFG, ""));
            d.delete();
        } finally {
            p.delete(true, true, new NullProgressMonitor());
        }
    }

    /** Evaluates the Robot Session shortcut's contextual-launch enablement (from plugin.xml) for a selection of {@code file}. */
    private static boolean shortcutEnabledOn(IFile file) throws CoreException {
        IConfigurationElement shortcut = java.util.Arrays.stream(Platform.getExtensionRegistry()
                .getConfigurationElementsFor("org.eclipse.debug.ui.launchShortcuts"))
                .filter(e -> "org.stagecraft.tools.robotSession.shortcut".equals(e.getAttribute("id"))).findFirst().orElseThrow();
        IConfigurationElement enablement = shortcut.getChildren("contextualLaunch")[0].getChildren("enablement")[0];
        Expression expression = ExpressionConverter.getDefault().perform(enablement);
        EvaluationContext context = new EvaluationContext(null, List.of(file));
        context.addVariable("selection", List.of(file));
        return expression.evaluate(context) == EvaluationResult.TRUE;
    }
}
