package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
}
