package org.stagecraft.tests.support;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.regex.Pattern;

import org.eclipse.core.runtime.ILogListener;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * A plug-in test fails when an ERROR reaches the Error Log while it runs (as lsp4e's tests do): a user
 * would have seen it there. Registered for every plug-in test by JUnit's extension auto-detection (each
 * test bundle's {@code META-INF/services}, switched on in the root pom). A test that provokes an error on
 * purpose says which with {@link LogsErrors} (on the class when the error may come after the test that
 * caused it has ended: failures are reported from the threads that see them).
 */
public final class ErrorLogGuard implements BeforeEachCallback, AfterEachCallback {
    private static final ExtensionContext.Namespace NAMESPACE = ExtensionContext.Namespace.create(ErrorLogGuard.class);
    /**
     * An extension registry's report of a test bundle's own contribution: the test bundles contribute broken
     * extensions on purpose (a missing class, a bad pattern, a duplicate id), and the registries' tests check
     * those reports; they come whenever a registry is read, in whichever test reads it first.
     */
    private static final Pattern TEST_FIXTURE_CONTRIBUTION = Pattern.compile("^org\\.stagecraft\\.core: plug-in org\\.stagecraft\\.[a-z.]+\\.tests, extension ");

    /** Errors a test (or all tests of a class) provokes on purpose: regular expressions their messages match. */
    @Retention(RetentionPolicy.RUNTIME)
    @Target({ ElementType.TYPE, ElementType.METHOD })
    public @interface LogsErrors {
        String[] value();
    }

    private static final class Recorder implements ILogListener {
        final List<IStatus> errors = Collections.synchronizedList(new ArrayList<>());

        @Override
        public void logging(IStatus status, String plugin) {
            collect(status);
        }

        private void collect(IStatus s) {
            if (s.getSeverity() == IStatus.ERROR && !s.isMultiStatus()) {
                errors.add(s);
            }
            for (IStatus child : s.getChildren()) {
                collect(child);
            }
        }
    }

    @Override
    public void beforeEach(ExtensionContext context) {
        Recorder r = new Recorder();
        Platform.addLogListener(r);
        context.getStore(NAMESPACE).put(Recorder.class, r);
    }

    @Override
    public void afterEach(ExtensionContext context) {
        Recorder r = context.getStore(NAMESPACE).remove(Recorder.class, Recorder.class);
        if (r == null) {
            return;
        }
        Platform.removeLogListener(r);
        List<Pattern> allowed = new ArrayList<>(List.of(TEST_FIXTURE_CONTRIBUTION));
        context.getTestMethod().map(m -> m.getAnnotation(LogsErrors.class)).ifPresent(a -> add(a, allowed));
        context.getTestClass().map(c -> c.getAnnotation(LogsErrors.class)).ifPresent(a -> add(a, allowed));
        List<String> unexpected = new ArrayList<>();
        synchronized (r.errors) {
            for (IStatus s : r.errors) {
                String text = s.getPlugin() + ": " + s.getMessage() + (s.getException() == null ? "" : " (" + s.getException() + ")");
                if (allowed.stream().noneMatch(p -> p.matcher(text).find())) {
                    unexpected.add(text);
                }
            }
        }
        if (!unexpected.isEmpty()) {
            throw new AssertionError("ERROR in the Error Log during " + context.getDisplayName() + ":\n  "
                    + String.join("\n  ", unexpected));
        }
    }

    private static void add(LogsErrors a, List<Pattern> allowed) {
        for (String p : a.value()) {
            allowed.add(Pattern.compile(p));
        }
    }
}
