package org.stagecraft.tools.ui.launch;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchConfigurationWorkingCopy;
import org.eclipse.debug.ui.AbstractLaunchConfigurationTab;
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

/** The Player cfg, the robot program, Player's program, port, restart policy, and where the spy log goes. */
public final class RobotSessionTab extends AbstractLaunchConfigurationTab {
    private Text cfg;
    private Text program;
    private Text player;
    private Text port;
    private Text restart;
    private Text logFolder;

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

    @Override
    public void setDefaults(ILaunchConfigurationWorkingCopy c) {
        c.setAttribute(LaunchAttributes.DEFAULT_PORT, SessionConfig.PLAYER_DEFAULT_PORT);
        c.setAttribute(LaunchAttributes.PLAYER_RESTART, "never");
        c.setAttribute(LaunchAttributes.LOG_FOLDER, LaunchAttributes.DEFAULT_LOG_FOLDER);
    }

    @Override
    public void initializeFrom(ILaunchConfiguration c) {
        try {
            cfg.setText(c.getAttribute(LaunchAttributes.CFG, ""));
            program.setText(c.getAttribute(LaunchAttributes.PROGRAM, ""));
            player.setText(c.getAttribute(LaunchAttributes.PLAYER, ""));
            port.setText(String.valueOf(c.getAttribute(LaunchAttributes.DEFAULT_PORT, SessionConfig.PLAYER_DEFAULT_PORT)));
            restart.setText(c.getAttribute(LaunchAttributes.PLAYER_RESTART, "never"));
            logFolder.setText(c.getAttribute(LaunchAttributes.LOG_FOLDER, LaunchAttributes.DEFAULT_LOG_FOLDER));
        } catch (CoreException e) {
            setErrorMessage(e.getMessage());
        }
    }

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
    }

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
