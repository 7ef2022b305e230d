package org.stagecraft.views.internal;

import java.util.concurrent.atomic.AtomicInteger;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.ui.IViewReference;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.handlers.HandlerUtil;
import org.stagecraft.views.RobotView;

/** Window ▸ New Robot View: opens another Robot View instance (a new secondary id). */
public final class NewRobotViewHandler extends AbstractHandler {
    private static final AtomicInteger NEXT = new AtomicInteger(1);

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public @Nullable Object execute(ExecutionEvent event) throws ExecutionException {
        IWorkbenchWindow window = HandlerUtil.getActiveWorkbenchWindowChecked(event);
        IWorkbenchPage page = window.getActivePage();
        try {
            page.showView(RobotView.ID, freeSecondaryId(page), IWorkbenchPage.VIEW_ACTIVATE);
        } catch (PartInitException e) {
            throw new ExecutionException("cannot open a Robot View: " + e.getMessage(), e);
        }
        return null;
    }

    static String freeSecondaryId(IWorkbenchPage page) {
        while (true) {
            String id = "view" + NEXT.getAndIncrement();
            boolean taken = false;
            for (IViewReference r : page.getViewReferences()) {
                taken |= RobotView.ID.equals(r.getId()) && id.equals(r.getSecondaryId());
            }
            if (!taken) {
                return id;
            }
        }
    }
}
