package org.stagecraft.replay.ui.internal;

import java.util.concurrent.RejectedExecutionException;

import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.swt.SWTException;
import org.eclipse.swt.widgets.Display;
import org.stagecraft.replay.session.SessionThreads;

/**
 * A replay session's threads in the workbench: background work is an Eclipse job (with progress in
 * the Progress view unless quiet), the owner is the display's UI thread.
 */
public final class WorkbenchThreads implements SessionThreads {
    /** Progress reported in this many units: a fraction of the work is shown to a thousandth. */
    private static final int UNITS = 1000;
    private final Display display;

    public WorkbenchThreads(Display display) {
        this.display = display;
    }

    @Override
    public Work background(String name, boolean quiet, Task task) {
        Job job = Job.create(name, (IProgressMonitor monitor) -> {
            monitor.beginTask(name, UNITS);
            int[] worked = { 0 };
            task.run(new Progress() {
                @Override
                public boolean cancelled() {
                    return monitor.isCanceled();
                }

                @Override
                public void done(double fraction) {
                    int now = (int) (Math.min(1, fraction) * UNITS);
                    if (now > worked[0]) {
                        monitor.worked(now - worked[0]);
                        worked[0] = now;
                    }
                }
            });
            monitor.done();
            return Status.OK_STATUS;
        });
        job.setSystem(quiet);
        job.schedule();
        return job::cancel;
    }

    @Override
    public void onOwner(Runnable r) {
        try {
            display.asyncExec(r);
        } catch (SWTException gone) {
            throw new RejectedExecutionException("the display is disposed", gone);
        }
    }
}
