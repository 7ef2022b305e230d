package org.stagecraft.replay.ui.internal;

import java.util.Locale;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.layout.RowLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.stagecraft.replay.session.Speeds;

/**
 * Play/pause, step back and forward one message, speed (0.1x to 16x), the replay time (type a time and
 * press Enter to seek) and the editor's other commands. Only widgets: what they do is the host's (the
 * buttons run the editor's {@link EditorCommand}s, the same a key bound to them runs).
 */
public final class TransportBar {
    /** The speeds offered, within the Replayer's 0.1x..16x. */
    private static final double[] SPEEDS = Speeds.offered();

    /** What the controls do: the buttons run the editor's commands. */
    public interface Host {
        void run(EditorCommand command);

        void speed(double speed);

        /** Seek to seconds after the log's start. */
        void seekSeconds(double seconds);
    }

    private final Composite root;
    private final Button play;
    private final Combo speed;
    private final Text time;
    private final Label length;
    private boolean editingTime;

    public TransportBar(Composite parent, Host host) {
        root = new Composite(parent, SWT.NONE);
        RowLayout layout = new RowLayout(SWT.HORIZONTAL);
        layout.wrap = true; // a narrow editor gets two rows rather than hidden controls
        layout.center = true;
        layout.marginTop = layout.marginBottom = 2;
        root.setLayout(layout);
        button("\u23EE", "To the start", () -> host.run(EditorCommand.TO_START));
        button("\u25C0|", "Step back one message (publishes it again)", () -> host.run(EditorCommand.STEP_BACK));
        play = button("\u25B6 Play", "Play / pause", () -> host.run(EditorCommand.PLAY_PAUSE));
        play.setLayoutData(new RowData(90, SWT.DEFAULT));
        button("|\u25B6", "Step forward one message (publishes it)", () -> host.run(EditorCommand.STEP_FORWARD));
        new Label(root, SWT.NONE).setText(" Speed:");
        speed = new Combo(root, SWT.READ_ONLY | SWT.DROP_DOWN);
        for (double s : SPEEDS) {
            speed.add(Speeds.text(s));
        }
        speed.select(3);
        speed.addListener(SWT.Selection, e -> host.speed(SPEEDS[speed.getSelectionIndex()]));
        new Label(root, SWT.NONE).setText(" Time:");
        time = new Text(root, SWT.BORDER | SWT.RIGHT);
        time.setLayoutData(new RowData(90, SWT.DEFAULT));
        time.setToolTipText("Seconds after the start of the log; Enter seeks");
        time.addListener(SWT.FocusIn, e -> editingTime = true);
        time.addListener(SWT.FocusOut, e -> editingTime = false);
        time.addListener(SWT.DefaultSelection, e -> {
            try {
                host.seekSeconds(Double.parseDouble(time.getText().strip().replace(',', '.')));
            } catch (NumberFormatException ex) {
                time.selectAll();
            }
            editingTime = false;
        });
        length = new Label(root, SWT.NONE);
        length.setText("/ 0.000 s");
        button("Reload", "Read the file again (a log still being written has grown)", () -> host.run(EditorCommand.RELOAD));
        button("Show in Robot View", "Open a Robot View that follows this log's replay", () -> host.run(EditorCommand.SHOW_IN_ROBOT_VIEW));
        button("Plot", "Open a Plot of this log", () -> host.run(EditorCommand.PLOT));
        button("Export \u25BE", "Export to CSV, Player writelog or MCAP with JSON channels", () -> host.run(EditorCommand.EXPORT));
    }

    private Button button(String text, String tip, Runnable run) {
        Button b = new Button(root, SWT.PUSH);
        b.setText(text);
        b.setToolTipText(tip);
        b.addListener(SWT.Selection, e -> run.run());
        return b;
    }

    public Composite control() {
        return root;
    }

    /** Shows the replay state: time since the start, play or pause, speed. */
    public void show(double seconds, double lengthSeconds, boolean playing, double currentSpeed) {
        if (!editingTime) {
            time.setText(String.format(Locale.ROOT, "%.3f", seconds));
        }
        length.setText(String.format(Locale.ROOT, "/ %.3f s", lengthSeconds));
        play.setText(playing ? "\u275A\u275A Pause" : "\u25B6 Play");
        for (int i = 0; i < SPEEDS.length; i++) {
            if (Math.abs(SPEEDS[i] - currentSpeed) < 1e-9 && speed.getSelectionIndex() != i) {
                speed.select(i);
            }
        }
        root.layout();
        root.getParent().layout();
    }

    public String timeText() {
        return time.getText();
    }

    public Combo speedCombo() {
        return speed;
    }

    public void setEnabled(boolean enabled) {
        for (var c : root.getChildren()) {
            if (!(c instanceof Button b) || !"Reload".equals(b.getText())) {
                c.setEnabled(enabled);
            }
        }
    }
}
