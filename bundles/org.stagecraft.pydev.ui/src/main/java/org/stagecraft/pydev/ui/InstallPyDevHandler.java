package org.stagecraft.pydev.ui;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.ui.handlers.HandlerUtil;

/** Help &gt; Install PyDev...: p2's install wizard. */
public final class InstallPyDevHandler extends AbstractHandler {
    @Override
    public Object execute(ExecutionEvent event) {
        PyDev.openInstall(HandlerUtil.getActiveWorkbenchWindow(event) != null ? HandlerUtil.getActiveWorkbenchWindow(event) : PyDev.window());
        return null;
    }
}
