package org.stagecraft.replay.session;

/** How a failure is shown to the user: the exception's class and message, no stack trace. */
public final class Failures {
    private Failures() {
    }

    /** The exception's class and message: some (ClosedChannelException) have no message at all. */
    public static String describe(Throwable e) {
        String m = e.getMessage();
        return e.getClass().getSimpleName() + (m == null || m.isBlank() ? "" : ": " + m);
    }
}
