package org.stagecraft.tools.ui.launch;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.ui.AbstractLaunchConfigurationTab;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.dialogs.ResourceListSelectionDialog;
import org.stagecraft.tools.process.RestartPolicy;
import org.stagecraft.tools.session.SessionConfig;
import org.stagecraft.tools.session.SpyOptions;

/**
 * The Player cfg, the robot program, Player's program, port, restart policy, where the spy log goes, and
 * how the spy treats robot programs: upstream grace, robot holds while suspended, the frozen world, the silence watchdog.
 */
public final class RobotSessionTab extends AbstractLaunchConfigurationTab {
    private @Nullable Text cfg;
    private @Nullable Text program;
    private @Nullable Text player;
    private @Nullable Text port;
    private @Nullable Text restart;
    private @Nullable Text logFolder;
    private @Nullable Text grace;
    private @Nullable Button holdWhenSuspended;
    private @Nullable Button freezeWorld;
    private @Nullable Button watchdog;
    private @Nullable Text watchdogSeconds;

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createControl(Composite parent) {
        Composite c = new Composite(parent, SWT.NONE);
        c.setLayout(new GridLayout(3, false));
        cfg = row(c, "Player cfg file:", true);
        program = row(c, "Robot program (.py):", true);
        player = row(c, "Player program (empty: preference):", false);
        port = row(c, "Default port (player -p):", false);
        restart = row(c, "Restart Player (never, on-failure:N, always:N):", false);
        logFolder = row(c, "Spy log folder in the project (empty: no log):", false);
        grace = row(c, "Seconds a robot program waits for Player (upstream grace):", false);
        holdWhenSuspended = check(c, "Hold the robots while the program is suspended",
                "While the debugger has the robot program suspended (breakpoint, step, Suspend), the Network Spy sends "
                        + "zero velocity to its robots and holds back its motion commands; resuming releases them. "
                        + "Also lets the emergency stop hold this session's robots.");
        freezeWorld = check(c, "Freeze the simulated world while the program is suspended (when Player runs Stage)",
                "While the robots are held (suspended in the debugger, a robot data breakpoint, the emergency stop), "
                        + "Stage's world stops too: simulated time, every model, every robot, including robots of other "
                        + "programs; after Resume it runs on from where it stopped. Stagecraft adds its own small driver "
                        + "to Player's copy of the cfg for this (built with g++ on first use).");
        watchdog = new Button(c, SWT.CHECK);
        watchdog.setText("Silence watchdog: hold a moving robot when its program sends nothing for (seconds):");
        watchdog.setToolTipText("Catches what the debugger does not tell: a program stuck in a loop, a crashed process "
                + "whose socket stays open, a long pause. The robot is held until its program sends again.");
        watchdog.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, false, false, 1, 1));
        watchdogSeconds = new Text(c, SWT.BORDER);
        watchdogSeconds.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        watchdogSeconds.addModifyListener(e -> updateLaunchConfigurationDialog());
        watchdog.addListener(SWT.Selection, e -> {
            watchdogSeconds.setEnabled(watchdog.getSelection());
            updateLaunchConfigurationDialog();
        });
        Label note = new Label(c, SWT.WRAP);
        note.setText("Player runs on a copy of the cfg with every port moved; the Network Spy listens on the original "
                + "ports, so the robot program connects as usual. Tools from Preferences > Stagecraft Tools start first.");
        note.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false, 3, 1));
        setControl(c);
    }

    private Text row(Composite c, String label, boolean browse) {
        new Label(c, SWT.NONE).setText(label);
        Text t = new Text(c, SWT.BORDER);
        t.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, browse ? 1 : 2, 1));
        t.addModifyListener(e -> updateLaunchConfigurationDialog());
        if (browse) {
            Button b = new Button(c, SWT.PUSH);
            b.setText("Browse...");
            b.addListener(SWT.Selection, e -> {
                ResourceListSelectionDialog d = new ResourceListSelectionDialog(getShell(),
                        ResourcesPlugin.getWorkspace().getRoot(), IResource.FILE);
                if (d.open() == Window.OK && d.getResult().length > 0 && d.getResult()[0] instanceof IFile f) {
                    t.setText(f.getFullPath().toString());
                }
            });
        }
        return t;
    }

    private Button check(Composite c, String label, String tooltip) {
        Button b = new Button(c, SWT.CHECK);
        b.setText(label);
        b.setToolTipText(tooltip);
        b.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 3, 1));
        b.addListener(SWT.Selection, e -> updateLaunchConfigurationDialog());
        return b;
    }

    /** Milliseconds as the seconds the user reads ("0.5"). */
    static String seconds(int millis) {
        return java.math.BigDecimal.valueOf(millis, 3).stripTrailingZeros().toPlainString();
    }

    /** The seconds the user typed as milliseconds; throws NumberFormatException for anything but a positive number. */
    static int millis(String seconds) {
        int ms = new java.math.BigDecimal(seconds.trim()).movePointRight(3).intValueExact();
        if (ms <= 0) {
            throw new NumberFormatException();
        }
        return ms;
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void setDefaults(ILaunchConfigurationWorkingCopy c) {
        c.setAttribute(LaunchAttributes.DEFAULT_PORT, SessionConfig.PLAYER_DEFAULT_PORT);
        c.setAttribute(LaunchAttributes.PLAYER_RESTART, "never");
        c.setAttribute(LaunchAttributes.LOG_FOLDER, LaunchAttributes.DEFAULT_LOG_FOLDER);
        c.setAttribute(LaunchAttributes.HOLD_WHEN_SUSPENDED, SpyOptions.DEFAULT.holdWhenSuspended());
        c.setAttribute(LaunchAttributes.FREEZE_WORLD, SpyOptions.DEFAULT.freezeWorld());
        c.setAttribute(LaunchAttributes.WATCHDOG, false);
        c.setAttribute(LaunchAttributes.WATCHDOG_MILLIS, LaunchAttributes.DEFAULT_WATCHDOG_MILLIS);
        c.setAttribute(LaunchAttributes.UPSTREAM_GRACE_SECONDS, (int) SpyOptions.DEFAULT.upstreamGrace().toSeconds());
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void initializeFrom(ILaunchConfiguration c) {
        try {
            cfg.setText(c.getAttribute(LaunchAttributes.CFG, ""));
            program.setText(c.getAttribute(LaunchAttributes.PROGRAM, ""));
            player.setText(c.getAttribute(LaunchAttributes.PLAYER, ""));
            port.setText(String.valueOf(c.getAttribute(LaunchAttributes.DEFAULT_PORT, SessionConfig.PLAYER_DEFAULT_PORT)));
            restart.setText(c.getAttribute(LaunchAttributes.PLAYER_RESTART, "never"));
            logFolder.setText(c.getAttribute(LaunchAttributes.LOG_FOLDER, LaunchAttributes.DEFAULT_LOG_FOLDER));
            grace.setText(String.valueOf(c.getAttribute(LaunchAttributes.UPSTREAM_GRACE_SECONDS,
                    (int) SpyOptions.DEFAULT.upstreamGrace().toSeconds())));
            holdWhenSuspended.setSelection(c.getAttribute(LaunchAttributes.HOLD_WHEN_SUSPENDED,
                    SpyOptions.DEFAULT.holdWhenSuspended()));
            freezeWorld.setSelection(c.getAttribute(LaunchAttributes.FREEZE_WORLD, SpyOptions.DEFAULT.freezeWorld()));
            watchdog.setSelection(c.getAttribute(LaunchAttributes.WATCHDOG, false));
            watchdogSeconds.setText(seconds(c.getAttribute(LaunchAttributes.WATCHDOG_MILLIS,
                    LaunchAttributes.DEFAULT_WATCHDOG_MILLIS)));
            watchdogSeconds.setEnabled(watchdog.getSelection());
        } catch (CoreException e) {
            setErrorMessage(e.getMessage());
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void performApply(ILaunchConfigurationWorkingCopy c) {
        c.setAttribute(LaunchAttributes.CFG, cfg.getText().trim());
        c.setAttribute(LaunchAttributes.PROGRAM, program.getText().trim());
        c.setAttribute(LaunchAttributes.PLAYER, player.getText().trim());
        try {
            c.setAttribute(LaunchAttributes.DEFAULT_PORT, Integer.parseInt(port.getText().trim()));
        } catch (NumberFormatException e) {
            // isValid reports it
        }
        c.setAttribute(LaunchAttributes.PLAYER_RESTART, restart.getText().trim());
        c.setAttribute(LaunchAttributes.LOG_FOLDER, logFolder.getText().trim());
        try {
            c.setAttribute(LaunchAttributes.UPSTREAM_GRACE_SECONDS, Integer.parseInt(grace.getText().trim()));
        } catch (NumberFormatException e) {
            // isValid reports it
        }
        c.setAttribute(LaunchAttributes.HOLD_WHEN_SUSPENDED, holdWhenSuspended.getSelection());
        c.setAttribute(LaunchAttributes.FREEZE_WORLD, freezeWorld.getSelection());
        c.setAttribute(LaunchAttributes.WATCHDOG, watchdog.getSelection());
        try {
            c.setAttribute(LaunchAttributes.WATCHDOG_MILLIS, millis(watchdogSeconds.getText()));
        } catch (NumberFormatException | ArithmeticException e) {
            // isValid reports it
        }
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public boolean isValid(ILaunchConfiguration launchConfig) {
        setErrorMessage(null);
        if (cfg.getText().isBlank()) {
            setErrorMessage("Choose the Player cfg file.");
            return false;
        }
        try {
            int p = Integer.parseInt(port.getText().trim());
            if (p < 1 || p > 65535) {
                throw new NumberFormatException();
            }
        } catch (NumberFormatException e) {
            setErrorMessage("Default port '" + port.getText() + "' is not 1..65535.");
            return false;
        }
        try {
            if (Integer.parseInt(grace.getText().trim()) < 0) {
                throw new NumberFormatException();
            }
        } catch (NumberFormatException e) {
            setErrorMessage("Upstream grace '" + grace.getText() + "' is not a number of seconds (0 or more).");
            return false;
        }
        if (watchdog.getSelection()) {
            try {
                millis(watchdogSeconds.getText());
            } catch (NumberFormatException | ArithmeticException e) {
                setErrorMessage("Watchdog timeout '" + watchdogSeconds.getText() + "' is not a positive number of seconds "
                        + "(at most three decimals).");
                return false;
            }
        }
        try {
            RestartPolicy.parse(restart.getText());
        } catch (IllegalArgumentException e) {
            setErrorMessage(e.getMessage());
            return false;
        }
        return true;
    }

    @Override
    public String getName() {
        return "Robot Session";
    }
}
