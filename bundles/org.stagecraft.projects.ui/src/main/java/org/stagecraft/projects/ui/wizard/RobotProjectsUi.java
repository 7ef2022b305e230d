package org.stagecraft.projects.ui.wizard;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.stagecraft.projects.ui.RobotProjects;

final class RobotProjectsUi {
    private RobotProjectsUi() {
    }

    static void log(IStatus status) {
        ILog.of(Platform.getBundle(RobotProjects.BUNDLE)).log(status);
    }
}
