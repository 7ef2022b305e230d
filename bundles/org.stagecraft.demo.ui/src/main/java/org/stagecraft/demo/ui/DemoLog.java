package org.stagecraft.demo.ui;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.jdt.annotation.Nullable;

/**
 * The demo's progress, in the Error Log and on the product's standard output: whoever started
 * {@code ./stagecraft demo} in a terminal sees what happens (and what went wrong) without opening a view.
 */
final class DemoLog {
    static final String BUNDLE = "org.stagecraft.demo.ui";
    private static final ILog LOG = ILog.of(DemoLog.class);

    private DemoLog() {
    }

    static void info(String message) {
        LOG.log(Status.info(message));
        System.out.println("stagecraft demo: " + message);
    }

    static void warn(String message) {
        LOG.log(Status.warning(message));
        System.out.println("stagecraft demo: " + message);
    }

    static void error(String message, @Nullable Throwable cause) {
        LOG.log(new Status(IStatus.ERROR, BUNDLE, message, cause));
        System.out.println("stagecraft demo: ERROR " + message);
    }
}
