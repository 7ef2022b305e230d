package org.stagecraft.replay.ui.internal;

import java.util.Locale;

import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.Dialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;

/** Asks for a time range in seconds from the log's start (blank: from the start, to the end). */
final class TimeRangeDialog extends Dialog {
    private final double length;
    private final String filter;
    private @Nullable Text fromText, untilText;
    private @Nullable Label problem;
    private @Nullable Double from, until;

    TimeRangeDialog(Shell shell, double length, String filter) {
        super(shell);
        this.length = length;
        this.filter = filter;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    protected void configureShell(Shell shell) {
        super.configureShell(shell);
        shell.setText("Export to CSV");
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    protected Control createDialogArea(Composite parent) {
        Composite c = (Composite) super.createDialogArea(parent);
        c.setLayout(new GridLayout(2, false));
        Label intro = new Label(c, SWT.WRAP);
        intro.setText(String.format(Locale.ROOT, "Messages the inspector's filter takes (%s), in seconds from the log's start "
                + "(0 to %.3f); blank for the whole log.", filter, length));
        GridData wide = new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1);
        wide.widthHint = 420;
        intro.setLayoutData(wide);
        new Label(c, SWT.NONE).setText("From (s):");
        fromText = new Text(c, SWT.BORDER);
        fromText.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        new Label(c, SWT.NONE).setText("Until (s):");
        untilText = new Text(c, SWT.BORDER);
        untilText.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        problem = new Label(c, SWT.NONE);
        problem.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        return c;
    }

    @Override
    protected void okPressed() {
        try {
            from = seconds(fromText.getText());
            until = seconds(untilText.getText());
        } catch (NumberFormatException e) {
            problem.setText("Times are numbers of seconds, e.g. 12.5");
            return;
        }
        if (from != null && until != null && until < from) {
            problem.setText("'Until' is before 'From'");
            return;
        }
        super.okPressed();
    }

    private static @Nullable Double seconds(String text) {
        String t = text.strip().replace(',', '.');
        return t.isEmpty() ? null : Double.valueOf(t);
    }

    @Nullable Double from() {
        return from;
    }

    @Nullable Double until() {
        return until;
    }
}
