package org.stagecraft.tools.ui.prefs;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.preference.PreferencePage;
import org.eclipse.jface.viewers.ArrayContentProvider;
import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.TableViewer;
import org.eclipse.jface.viewers.TableViewerColumn;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchPreferencePage;
import org.osgi.service.prefs.BackingStoreException;
import org.stagecraft.tools.types.ToolDefinition;

/** Preferences &gt; Stagecraft Tools: the Player and Python programs and the user's tools. */
public final class ToolsPreferencePage extends PreferencePage implements IWorkbenchPreferencePage {
    private @Nullable Text player;
    private @Nullable Text python;
    private @Nullable TableViewer table;
    private final List<ToolDefinition> tools = new ArrayList<>();

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void init(IWorkbench workbench) {
        setDescription("Programs a Robot Session starts. Tools run before Player, in this order; "
                + "each is waited for until it is ready.");
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    protected Control createContents(Composite parent) {
        Composite c = new Composite(parent, SWT.NONE);
        c.setLayout(new GridLayout(2, false));
        player = field(c, "Player program (path, or name on PATH):", ToolPreferences.get(ToolPreferences.PLAYER));
        python = field(c, "Python interpreter (without PyDev):", ToolPreferences.get(ToolPreferences.PYTHON));

        Label l = new Label(c, SWT.NONE);
        l.setText("Tools:");
        l.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false, 2, 1));
        table = new TableViewer(c, SWT.BORDER | SWT.FULL_SELECTION | SWT.SINGLE);
        table.getTable().setHeaderVisible(true);
        column("Name", 120, ToolDefinition::name);
        column("Command", 200, d -> (d.command() + " " + d.arguments()).trim());
        column("Ready when", 120, d -> d.readiness().isBlank() ? "started" : d.readiness());
        column("Restart", 90, ToolDefinition::restart);
        column("On", 40, d -> d.enabled() ? "yes" : "no");
        table.setContentProvider(ArrayContentProvider.getInstance());
        tools.addAll(ToolPreferences.tools());
        table.setInput(tools);
        table.getTable().setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));

        Composite buttons = new Composite(c, SWT.NONE);
        buttons.setLayout(new GridLayout(1, true));
        buttons.setLayoutData(new GridData(SWT.FILL, SWT.TOP, false, false));
        button(buttons, "Add...", () -> edit(-1));
        button(buttons, "Edit...", () -> edit(table.getTable().getSelectionIndex()));
        button(buttons, "Remove", () -> {
            int i = table.getTable().getSelectionIndex();
            if (i >= 0) {
                tools.remove(i);
                table.refresh();
            }
        });
        table.addDoubleClickListener(e -> edit(table.getTable().getSelectionIndex()));
        return c;
    }

    private void edit(int index) {
        ToolDefinition current = index >= 0 ? tools.get(index) : null;
        if (index >= 0 && ((IStructuredSelection) table.getSelection()).isEmpty()) {
            return;
        }
        ToolDialog dialog = new ToolDialog(getShell(), current);
        if (dialog.open() == Window.OK) {
            ToolDefinition result = Objects.requireNonNull(dialog.result()); // OK sets it
            if (index >= 0) {
                tools.set(index, result);
            } else {
                tools.add(result);
            }
            table.refresh();
        }
    }

    private Text field(Composite c, String label, String value) {
        new Label(c, SWT.NONE).setText(label);
        Text t = new Text(c, SWT.BORDER);
        t.setText(value);
        t.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        return t;
    }

    private void column(String title, int width, java.util.function.Function<ToolDefinition, String> text) {
        TableViewerColumn col = new TableViewerColumn(table, SWT.NONE);
        col.getColumn().setText(title);
        col.getColumn().setWidth(width);
        col.setLabelProvider(new ColumnLabelProvider() {
            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public String getText(Object element) {
                return text.apply((ToolDefinition) element);
            }
        });
    }

    private static void button(Composite c, String text, Runnable action) {
        Button b = new Button(c, SWT.PUSH);
        b.setText(text);
        b.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        b.addListener(SWT.Selection, e -> action.run());
    }

    @Override
    protected void performDefaults() {
        player.setText(ToolPreferences.DEFAULT_PLAYER);
        python.setText(ToolPreferences.DEFAULT_PYTHON);
        super.performDefaults();
    }

    @Override
    public boolean performOk() {
        try {
            ToolPreferences.set(ToolPreferences.PLAYER, player.getText().trim());
            ToolPreferences.set(ToolPreferences.PYTHON, python.getText().trim());
            ToolPreferences.setTools(tools);
            return true;
        } catch (BackingStoreException e) {
            setErrorMessage("cannot save the preferences: " + e.getMessage());
            return false;
        }
    }
}
