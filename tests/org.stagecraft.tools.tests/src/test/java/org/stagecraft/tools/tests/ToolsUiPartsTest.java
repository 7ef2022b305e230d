package org.stagecraft.tools.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.core.ILaunchManager;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.junit.jupiter.api.Test;
import org.stagecraft.tools.types.ToolDefinition;
import org.stagecraft.tools.ui.launch.LaunchAttributes;
import org.stagecraft.tools.ui.launch.RobotSessionTab;
import org.stagecraft.tools.ui.prefs.ToolPreferences;
import org.stagecraft.tools.ui.prefs.ToolsPreferencePage;

/** The preference page and the launch tab read and write what they show. */
class ToolsUiPartsTest {

    private static <T> T onUi(java.util.function.Supplier<T> s) {
        AtomicReference<T> r = new AtomicReference<>();
        AtomicReference<RuntimeException> err = new AtomicReference<>();
        Display.getDefault().syncExec(() -> {
            try {
                r.set(s.get());
            } catch (RuntimeException e) {
                err.set(e);
            }
        });
        if (err.get() != null) {
            throw err.get();
        }
        return r.get();
    }

    private static List<Text> texts(Control c, List<Text> into) {
        if (c instanceof Text t) {
            into.add(t);
        }
        if (c instanceof Composite comp) {
            for (Control child : comp.getChildren()) {
                texts(child, into);
            }
        }
        return into;
    }

    @Test
    void thePreferencePageShowsAndSavesThePrograms() throws Exception {
        ToolPreferences.setTools(List.of(ToolDefinition.of("sim", "stage", "-g")));
        try {
            String saved = onUi(() -> {
                Shell shell = new Shell(Display.getDefault());
                try {
                    ToolsPreferencePage page = new ToolsPreferencePage();
                    page.init(null);
                    page.createControl(shell);
                    List<Text> fields = texts(page.getControl(), new java.util.ArrayList<>());
                    assertEquals("player", fields.get(0).getText());
                    assertEquals("python3", fields.get(1).getText());
                    fields.get(0).setText("/opt/player/bin/player");
                    assertTrue(page.performOk());
                    page.dispose();
                    return ToolPreferences.get(ToolPreferences.PLAYER);
                } finally {
                    shell.dispose();
                }
            });
            assertEquals("/opt/player/bin/player", saved);
            assertEquals(List.of(ToolDefinition.of("sim", "stage", "-g")), ToolPreferences.tools(), "the tools are kept");
        } finally {
            ToolPreferences.set(ToolPreferences.PLAYER, "player");
            ToolPreferences.setTools(List.of());
        }
    }

    @Test
    void theRobotSessionTabRoundTripsItsAttributesAndRejectsBadInput() throws Exception {
        ILaunchManager lm = DebugPlugin.getDefault().getLaunchManager();
        ILaunchConfigurationWorkingCopy wc = lm.getLaunchConfigurationType(LaunchAttributes.TYPE).newInstance(null, "tab-test");
        wc.setAttribute(LaunchAttributes.CFG, "/robot/worlds/six-robots.cfg");
        wc.setAttribute(LaunchAttributes.PROGRAM, "/robot/avoid.py");
        wc.setAttribute(LaunchAttributes.DEFAULT_PORT, 7000);
        wc.setAttribute(LaunchAttributes.PLAYER_RESTART, "on-failure:2");
        wc.setAttribute(LaunchAttributes.LOG_FOLDER, "logs");
        Map<String, Object> result = onUi(() -> {
            Shell shell = new Shell(Display.getDefault(), SWT.NONE);
            try {
                RobotSessionTab tab = new RobotSessionTab();
                tab.createControl(shell);
                tab.initializeFrom(wc);
                List<Text> fields = texts(tab.getControl(), new java.util.ArrayList<>());
                boolean validBefore = tab.isValid(wc);
                fields.get(3).setText("70000");
                boolean validBadPort = tab.isValid(wc);
                String portMessage = tab.getErrorMessage();
                fields.get(3).setText("7001");
                fields.get(4).setText("sometimes");
                boolean validBadRestart = tab.isValid(wc);
                fields.get(4).setText("always:1");
                tab.performApply(wc);
                return Map.of("before", validBefore, "badPort", validBadPort, "portMessage", portMessage,
                        "badRestart", validBadRestart, "cfgField", fields.get(0).getText());
            } finally {
                shell.dispose();
            }
        });
        assertEquals(true, result.get("before"));
        assertEquals(false, result.get("badPort"));
        assertTrue(((String) result.get("portMessage")).contains("70000"));
        assertEquals(false, result.get("badRestart"));
        assertEquals("/robot/worlds/six-robots.cfg", result.get("cfgField"));
        assertEquals(7001, wc.getAttribute(LaunchAttributes.DEFAULT_PORT, 0));
        assertEquals("always:1", wc.getAttribute(LaunchAttributes.PLAYER_RESTART, ""));
        assertEquals("/robot/avoid.py", wc.getAttribute(LaunchAttributes.PROGRAM, ""));
        assertEquals("logs", wc.getAttribute(LaunchAttributes.LOG_FOLDER, ""));
        assertFalse(wc.getAttribute(LaunchAttributes.CFG, "").isEmpty());
    }
}
