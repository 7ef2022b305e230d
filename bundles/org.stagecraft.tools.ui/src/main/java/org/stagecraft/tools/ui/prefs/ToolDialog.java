package org.stagecraft.tools.ui.prefs;

import java.util.List;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.stagecraft.tools.types.GenericToolType;
import org.stagecraft.tools.types.ToolDefinition;
import org.stagecraft.tools.ui.registry.ToolTypeExtensionRegistry;

/** Edits one user tool; checks it with its type before it can be saved. */
final class ToolDialog extends TitleAreaDialog {
    private final ToolDefinition initial;
    private @Nullable ToolDefinition result;
    private @Nullable List<ToolTypeExtensionRegistry.Contribution> types;
    private @Nullable Text name;
    private @Nullable Combo type;
    private @Nullable Text command;
    private @Nullable Text arguments;
    private @Nullable Text workingDir;
    private @Nullable Text environment;
    private @Nullable Text readiness;
    private @Nullable Text restart;
    private @Nullable Text readyWithin;
    private @Nullable Button enabled;

    ToolDialog(Shell shell, @Nullable ToolDefinition initial) {
        super(shell);
        this.initial = initial != null ? initial : ToolDefinition.of("", "", "");
    }

    @Nullable ToolDefinition result() {
        return result;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    protected Control createDialogArea(Composite parent) {
        setTitle("External tool");
        setMessage("Ready when: empty (as soon as it runs), port:PORT[,PORT], port:HOST:PORT or line:REGEX. "
                + "Restart: never, on-failure:N or always:N.");
        Composite area = (Composite) super.createDialogArea(parent);
        Composite c = new Composite(area, SWT.NONE);
        c.setLayout(new GridLayout(2, false));
        c.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        name = text(c, "Name:", initial.name(), SWT.BORDER);
        new Label(c, SWT.NONE).setText("Type:");
        type = new Combo(c, SWT.READ_ONLY);
        types = ToolTypeExtensionRegistry.load();
        for (ToolTypeExtensionRegistry.Contribution t : types) {
            type.add(t.name());
            if (t.id().equals(initial.type())) {
                type.select(type.getItemCount() - 1);
            }
        }
        if (type.getSelectionIndex() < 0 && type.getItemCount() > 0) {
            type.select(0);
        }
        command = text(c, "Command:", initial.command(), SWT.BORDER);
        arguments = text(c, "Arguments:", initial.arguments(), SWT.BORDER);
        workingDir = text(c, "Working directory:", initial.workingDir(), SWT.BORDER);
        environment = text(c, "Environment (KEY=value lines):", ToolPreferences.environmentText(initial.environment()),
                SWT.BORDER | SWT.MULTI | SWT.V_SCROLL);
        ((GridData) environment.getLayoutData()).heightHint = 60;
        readiness = text(c, "Ready when:", initial.readiness(), SWT.BORDER);
        readyWithin = text(c, "Ready within (s):", String.valueOf(initial.readyWithinSeconds()), SWT.BORDER);
        restart = text(c, "Restart:", initial.restart(), SWT.BORDER);
        new Label(c, SWT.NONE);
        enabled = new Button(c, SWT.CHECK);
        enabled.setText("Start it in Robot Sessions");
        enabled.setSelection(initial.enabled());
        return area;
    }

    private static Text text(Composite c, String label, String value, int style) {
        new Label(c, SWT.NONE).setText(label);
        Text t = new Text(c, style);
        t.setText(value);
        GridData gd = new GridData(SWT.FILL, SWT.CENTER, true, false);
        gd.widthHint = 360;
        t.setLayoutData(gd);
        return t;
    }

    @Override
    protected void okPressed() {
        int seconds;
        try {
            seconds = Integer.parseInt(readyWithin.getText().trim());
        } catch (NumberFormatException e) {
            setErrorMessage("Ready within: '" + readyWithin.getText() + "' is not a number of seconds");
            return;
        }
        if (name.getText().isBlank()) {
            setErrorMessage("The tool needs a name (it names its console and its row in the Tools view).");
            return;
        }
        String typeId = type.getSelectionIndex() >= 0 ? types.get(type.getSelectionIndex()).id() : GenericToolType.ID;
        ToolDefinition d = new ToolDefinition(name.getText().trim(), typeId, command.getText().trim(), arguments.getText(),
                workingDir.getText().trim(), ToolPreferences.environment(environment.getText()), readiness.getText().trim(),
                restart.getText().trim(), seconds, enabled.getSelection());
        try {
            types.get(Math.max(0, type.getSelectionIndex())).type().toSpec(d);
        } catch (RuntimeException e) {
            setErrorMessage(e.getMessage());
            return;
        }
        result = d;
        super.okPressed();
    }
}
