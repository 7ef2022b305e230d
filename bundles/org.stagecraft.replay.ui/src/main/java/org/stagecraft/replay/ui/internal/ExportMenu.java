package org.stagecraft.replay.ui.internal;

import java.nio.file.Path;
import java.util.Locale;
import java.util.Objects;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.jobs.IJobChangeEvent;
import org.eclipse.core.runtime.jobs.JobChangeAdapter;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.dialogs.ErrorDialog;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.FileDialog;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Shell;
import org.stagecraft.replay.export.ExportFilter;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.ui.SessionLogEditor;

/**
 * The editor's Export menu: CSV of a time range with the inspector's filter, the whole log as a Player
 * writelog file, the whole log as MCAP with decoded JSON channels (Foxglove). Asks where, then runs a
 * {@link LogExport} job on the editor's file (its own reading, untouched by reloads) and reports the result.
 */
public final class ExportMenu {
    private ExportMenu() {
    }

    public static void show(Composite anchor, SessionLogEditor editor) {
        Menu menu = new Menu(anchor.getShell(), SWT.POP_UP);
        item(menu, "CSV (time range, inspector filter)\u2026", () -> csv(anchor.getShell(), editor));
        item(menu, "Player writelog (whole log)\u2026", () -> whole(anchor.getShell(), editor, LogExport.Kind.WRITELOG, "*.log"));
        item(menu, "MCAP with JSON channels, for Foxglove (whole log)\u2026",
                () -> whole(anchor.getShell(), editor, LogExport.Kind.MCAP, "*.mcap"));
        Point at = anchor.toDisplay(Math.max(0, anchor.getSize().x - 200), anchor.getSize().y);
        menu.setLocation(at);
        menu.setVisible(true);
    }

    private static void item(Menu menu, String text, Runnable run) {
        MenuItem i = new MenuItem(menu, SWT.PUSH);
        i.setText(text);
        i.addListener(SWT.Selection, e -> run.run());
    }

    /** The inspector's stream pattern and text as an export filter over [from, until] seconds. */
    public static ExportFilter filterOf(SessionLogEditor editor, @Nullable Double fromSeconds, @Nullable Double untilSeconds) {
        var f = editor.inspector().filter();
        var pattern = f.patternText().isEmpty() ? null
                : org.stagecraft.replay.analysis.StreamSelector.parse(f.patternText(), editor.columns().registry());
        return new ExportFilter(fromSeconds, untilSeconds, pattern, f.text().isEmpty() ? null : f.text());
    }

    private static void csv(Shell shell, SessionLogEditor editor) {
        SessionLog log = editor.log();
        if (log == null) {
            return;
        }
        double length = (log.endNanos() - log.startNanos()) / 1e9;
        TimeRangeDialog range = new TimeRangeDialog(shell, length, editor.inspector().filter().toString());
        if (range.open() != TimeRangeDialog.OK) {
            return;
        }
        Path out = ask(shell, editor, "*.csv");
        if (out != null) {
            run(shell, editor, LogExport.Kind.CSV, filterOf(editor, range.from(), range.until()), out);
        }
    }

    private static void whole(Shell shell, SessionLogEditor editor, LogExport.Kind kind, String extension) {
        Path out = ask(shell, editor, extension);
        if (out != null && editor.log() != null) {
            run(shell, editor, kind, ExportFilter.all(), out);
        }
    }

    private static @Nullable Path ask(Shell shell, SessionLogEditor editor, String extension) {
        FileDialog d = new FileDialog(shell, SWT.SAVE);
        d.setOverwrite(true);
        d.setFilterExtensions(new String[] { extension, "*" });
        Path file = editor.file();
        String base = file.getFileName().toString().replaceFirst("(\\.trace\\.jsonl|\\.[A-Za-z0-9]+)$", "");
        d.setFilterPath(file.toAbsolutePath().getParent().toString());
        d.setFileName(base + "-export" + extension.substring(1).toLowerCase(Locale.ROOT));
        String chosen = d.open();
        return chosen == null ? null : Path.of(chosen);
    }

    private static void run(Shell shell, SessionLogEditor editor, LogExport.Kind kind, ExportFilter filter, Path out) {
        // an editor with a log has its file
        var job = LogExport.start(Objects.requireNonNull(editor.file()), kind, filter, editor.columns().registry(), out);
        job.addJobChangeListener(new JobChangeAdapter() {
            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public void done(IJobChangeEvent event) {
                IStatus s = event.getResult();
                shell.getDisplay().asyncExec(() -> {
                    if (shell.isDisposed()) {
                        return;
                    }
                    if (s.isOK()) {
                        MessageDialog.openInformation(shell, "Export", s.getMessage());
                    } else {
                        ErrorDialog.openError(shell, "Export", null, s);
                    }
                });
            }
        });
    }
}
