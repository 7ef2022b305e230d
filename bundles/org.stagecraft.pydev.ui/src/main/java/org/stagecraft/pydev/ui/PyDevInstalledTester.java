package org.stagecraft.pydev.ui;

import org.eclipse.core.expressions.PropertyTester;
import org.eclipse.jdt.annotation.NonNullByDefault;

/** {@code org.stagecraft.pydev.ui.installed}: whether PyDev is installed (hides Help &gt; Install PyDev... then). */
public final class PyDevInstalledTester extends PropertyTester {
    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public boolean test(Object receiver, String property, Object[] args, Object expectedValue) {
        return PyDev.installed();
    }
}
