package org.stagecraft.pydev.ui;

import java.util.Objects;
import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.handlers.HandlerUtil;

/** Help &gt; Install PyDev...: p2's install wizard. */
public final class InstallPyDevHandler extends AbstractHandler {
    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) {
        IWorkbenchWindow active = HandlerUtil.getActiveWorkbenchWindow(event);
        PyDev.openInstall(active != null ? active : Objects.requireNonNull(PyDev.window()));
        return null;
    }
}
