package org.stagecraft.pydev.ui;

import org.eclipse.core.expressions.PropertyTester;

/** {@code org.stagecraft.pydev.ui.installed}: whether PyDev is installed (hides Help &gt; Install PyDev... then). */
public final class PyDevInstalledTester extends PropertyTester {
    @Override
    public boolean test(Object receiver, String property, Object[] args, Object expectedValue) {
        return PyDev.installed();
    }
}
