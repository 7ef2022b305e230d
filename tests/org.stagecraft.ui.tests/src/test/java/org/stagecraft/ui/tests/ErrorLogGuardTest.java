package org.stagecraft.ui.tests;

import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.Status;
import org.junit.jupiter.api.Test;
import org.stagecraft.tests.support.ErrorLogGuard.LogsErrors;

/**
 * The Error Log guard of every plug-in test (tests.support's ErrorLogGuard, registered by JUnit's
 * auto-detection): an error a test provokes on purpose, named with {@link LogsErrors}, does not fail it.
 * (An error nobody named fails the test that was running: checked by hand with a test like this one without
 * the annotation, which failed with "ERROR in the Error Log during ...".)
 */
class ErrorLogGuardTest {
    @Test
    @LogsErrors("an error this test logs on purpose")
    void anErrorTheTestNamesIsAllowed() {
        ILog.of(ErrorLogGuardTest.class).log(Status.error("an error this test logs on purpose"));
    }
}
