package org.stagecraft.pydev.tests;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;

import org.eclipse.core.runtime.NullProgressMonitor;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.python.pydev.ast.interpreter_managers.InterpreterInfo;
import org.python.pydev.ast.interpreter_managers.InterpreterManagersAPI;
import org.python.pydev.ast.interpreter_managers.PythonInterpreterManager;
import org.python.pydev.core.IInterpreterInfo;
import org.python.pydev.core.IInterpreterManager;
import org.python.pydev.plugin.preferences.PydevRootPrefs;
import org.python.pydev.shared_core.structure.Tuple;

/** A Python interpreter configured in PyDev the way its interpreter preference page does it. */
final class PyDevInterpreter {
    /** The interpreter configured in this JVM, or null. */
    private static String configured;

    private PyDevInterpreter() {
    }

    /**
     * Makes {@code python} PyDev's only (so default) interpreter: PyDev runs its own
     * pysrc/interpreterInfo.py with it. Also turns off the "preferred settings" dialog PyDev's editor
     * would open.
     */
    static synchronized void configure(String python) throws Exception {
        if (python.equals(configured)) {
            // once per test JVM: setting the same interpreter again makes PyDev read its libraries anew,
            // and a launch made meanwhile gets a path without them
            return;
        }
        IEclipsePreferences pydevPrefs = InstanceScope.INSTANCE.getNode("org.python.pydev");
        pydevPrefs.putBoolean(PydevRootPrefs.CHECK_PREFERRED_PYDEV_SETTINGS, false);
        pydevPrefs.flush();
        Tuple<InterpreterInfo, String> created = PythonInterpreterManager.doCreateInterpreterInfo(python,
                new NullProgressMonitor(), false);
        assertNotNull(created, "PyDev made no interpreter info for " + python);
        assertTrue(created.o2.contains("<xml>"), "PyDev's interpreterInfo.py printed its XML: " + created.o2);
        IInterpreterManager manager = InterpreterManagersAPI.getPythonInterpreterManager();
        manager.setInfos(new IInterpreterInfo[] {created.o1}, Set.of(created.o1.getExecutableOrJar()), new NullProgressMonitor());
        assertTrue(manager.isConfigured(), "PyDev has a default interpreter");
        configured = python;
    }

    /** The first {@code name} on PATH. */
    static String onPath(String name) {
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
            Path p = Path.of(dir, name);
            if (Files.isExecutable(p)) {
                return p.toString();
            }
        }
        throw new AssertionError(name + " is not on PATH: the PyDev tier needs it");
    }
}
