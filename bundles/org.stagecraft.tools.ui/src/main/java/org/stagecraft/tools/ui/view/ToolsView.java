package org.stagecraft.tools.ui.view;

import java.util.function.Function;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.viewers.ArrayContentProvider;
import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.TableViewer;
import org.eclipse.jface.viewers.TableViewerColumn;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.part.ViewPart;
import org.stagecraft.tools.ui.launch.SessionHolds;

/** Every part of the running Robot Sessions with its state, process id, restarts and last exit code. */
public final class ToolsView extends ViewPart {
    public static final String ID = "org.stagecraft.tools.ui.toolsView";
    private @Nullable TableViewer table;
    private final Color held = new Color(226, 214, 248);
    private final Runnable refresh = () -> {
        Display d = table == null ? null : table.getControl().getDisplay();
        if (d != null && !d.isDisposed()) {
            d.asyncExec(this::refresh);
        }
    };

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createPartControl(Composite parent) {
        table = new TableViewer(parent, SWT.FULL_SELECTION | SWT.BORDER);
        table.getTable().setHeaderVisible(true);
        table.getTable().setLinesVisible(true);
        column("Session", 160, ToolsModel.Row::session);
        column("Part", 120, ToolsModel.Row::part);
        column("State", 90, r -> r.state().name().toLowerCase());
        column("PID", 70, r -> r.pid() > 0 ? String.valueOf(r.pid()) : "");
        column("Restarts", 70, r -> String.valueOf(r.restarts()));
        column("Last exit", 70, r -> r.lastExit() == null ? "" : String.valueOf(r.lastExit()));
        column("Detail", 320, ToolsModel.Row::detail);
        table.setContentProvider(ArrayContentProvider.getInstance());
        table.setInput(ToolsModel.get().rows());
        ToolsModel.get().addListener(refresh);
    }

    private void refresh() {
        if (table != null && !table.getControl().isDisposed()) {
            table.setInput(ToolsModel.get().rows());
        }
    }

    /** The rows shown now (for tests and accessibility tools). */
    public int rowCount() {
        return table.getTable().getItemCount();
    }

    public String cell(int row, int column) {
        return table.getTable().getItem(row).getText(column);
    }

    private void column(String title, int width, Function<ToolsModel.Row, String> text) {
        TableViewerColumn c = new TableViewerColumn(table, SWT.NONE);
        c.getColumn().setText(title);
        c.getColumn().setWidth(width);
        c.setLabelProvider(new ColumnLabelProvider() {
            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public String getText(Object element) {
                return text.apply((ToolsModel.Row) element);
            }

            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public Color getBackground(Object element) {
                // a session whose robots are held stands out, in the hold colour of the other views
                return SessionHolds.isHeldDetail(((ToolsModel.Row) element).detail()) ? held : null;
            }
        });
    }

    @Override
    public void setFocus() {
        table.getControl().setFocus();
    }

    @Override
    public void dispose() {
        ToolsModel.get().removeListener(refresh);
        super.dispose();
    }
}
