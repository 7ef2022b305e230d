package org.stagecraft.tools.ui.launch;

import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.debug.core.DebugPlugin;
import org.eclipse.debug.core.ILaunch;
import org.eclipse.debug.core.ILaunchConfiguration;
import org.eclipse.debug.core.ILaunchesListener2;
import org.eclipse.debug.core.model.LaunchConfigurationDelegate;
import org.eclipse.jdt.annotation.NonNullByDefault;
import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.core.extensions.Contributions;
import org.stagecraft.tools.session.RobotSession;
import org.stagecraft.tools.session.SessionException;
import org.stagecraft.tools.ui.view.ToolsModel;

/**
 * Starts a Robot Session as one launch: the user's tools, Player on the rewritten cfg, the spy on
 * the original ports (log in the project), then the robot program. Each part is a process of the
 * launch (its own console, its line in the Debug view); terminating the launch, or any part of the
 * session, stops all of it. If the session cannot start, nothing of it is left running and the
 * launch fails with the reason (file:line, port, program).
 */
public final class RobotSessionLaunchDelegate extends LaunchConfigurationDelegate {

    /** The running sessions' parts, by launch (for tests and the Tools view). */
    /** The family of the jobs that show a stopped session's new spy log in its project. */
    public static final Object LOG_REFRESH = new Object();
    private static final java.util.Map<ILaunch, SessionParts> RUNNING = new java.util.concurrent.ConcurrentHashMap<>();

    public static @Nullable SessionParts partsOf(ILaunch launch) {
        return RUNNING.get(launch);
    }

    @NonNullByDefault({}) // the parameters as the unannotated library gives them
    @Override
    public void launch(ILaunchConfiguration configuration, String mode, ILaunch launch, IProgressMonitor monitor)
            throws CoreException {
        SubMonitor m = SubMonitor.convert(monitor, "Robot Session " + configuration.getName(), 3);
        SessionParts parts = new SessionParts(launch, configuration.getName());
        SessionSettings settings;
        try {
            settings = SessionSettings.read(configuration);
        } catch (CoreException e) {
            parts.failed(e.getMessage(), null);
            throw e;
        }
        ToolsModel.get().removeSession(configuration.getName());
        m.subTask("starting tools, Player and the spy");
        RobotSession session;
        try {
            // the spy decodes what plug-ins contribute too
            session = RobotSession.start(settings.config(), Contributions.workbench().codecs(), parts);
        } catch (SessionException e) {
            parts.failed(e.getMessage(), e);
            throw new CoreException(Status.error("Robot Session '" + configuration.getName() + "' did not start: "
                    + e.getMessage(), e));
        }
        m.worked(2);
        parts.started(session);
        RUNNING.put(launch, parts);
        stopWhenLaunchEnds(launch, parts, settings);
        if (settings.program() != null) {
            m.subTask("starting " + settings.program().getName());
            try {
                RobotProgram.start(configuration, mode, launch, settings, parts, m.split(1));
            } catch (CoreException e) {
                parts.stopNow();
                throw e;
            }
        }
    }

    /** Terminate or removal of the launch stops the session; afterwards the new log appears in the project. */
    private static void stopWhenLaunchEnds(ILaunch launch, SessionParts parts, SessionSettings settings) {
        ILaunchesListener2 listener = new ILaunchesListener2() {
            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public void launchesTerminated(ILaunch[] launches) {
                for (ILaunch l : launches) {
                    if (l == launch) {
                        ended();
                    }
                }
            }

            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public void launchesRemoved(ILaunch[] launches) {
                for (ILaunch l : launches) {
                    if (l == launch) {
                        ended();
                    }
                }
            }

            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public void launchesAdded(ILaunch[] launches) {
            }

            @NonNullByDefault({}) // the parameters as the unannotated library gives them
            @Override
            public void launchesChanged(ILaunch[] launches) {
            }

            private void ended() {
                DebugPlugin.getDefault().getLaunchManager().removeLaunchListener(this);
                parts.stopInBackground();
                if (settings.logFolder() != null) {
                    Job refresh = new Job("Refresh spy logs") {
                        @NonNullByDefault({}) // the parameters as the unannotated library gives them
                        @Override
                        protected IStatus run(IProgressMonitor mon) {
                            try {
                                settings.logFolder().refreshLocal(IResource.DEPTH_ONE, mon);
                            } catch (CoreException e) {
                                return e.getStatus();
                            }
                            return Status.OK_STATUS;
                        }

                        @Override
                        public boolean belongsTo(@Nullable Object family) {
                            return family == LOG_REFRESH;
                        }
                    };
                    refresh.setSystem(true);
                    refresh.schedule();
                }
                // last: whoever waits for the session to be done (the exit) sees the refresh scheduled by then
                RUNNING.remove(launch);
            }
        };
        DebugPlugin.getDefault().getLaunchManager().addLaunchListener(listener);
        // a launch can end before the listener is in place (e.g. Player crashed at once)
        if (launch.isTerminated()) {
            listener.launchesTerminated(new ILaunch[] {launch});
        }
    }
}
