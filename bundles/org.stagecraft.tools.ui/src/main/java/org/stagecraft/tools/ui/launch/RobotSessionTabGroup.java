package org.stagecraft.tools.ui.launch;

import org.eclipse.debug.ui.AbstractLaunchConfigurationTabGroup;
import org.eclipse.debug.ui.CommonTab;
import org.eclipse.debug.ui.EnvironmentTab;
import org.eclipse.debug.ui.ILaunchConfigurationDialog;
import org.eclipse.debug.ui.ILaunchConfigurationTab;
import org.eclipse.jdt.annotation.NonNullByDefault;

/** Robot Session tab, the robot program's environment, and the common settings. */
public final class RobotSessionTabGroup extends AbstractLaunchConfigurationTabGroup {
    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void createTabs(ILaunchConfigurationDialog dialog, String mode) {
        setTabs(new ILaunchConfigurationTab[] {new RobotSessionTab(), new EnvironmentTab(), new CommonTab()});
    }
}
