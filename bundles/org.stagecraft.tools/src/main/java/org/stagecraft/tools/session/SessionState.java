package org.stagecraft.tools.session;

/** Where a robot session is in its life, as a user should see it. */
public enum SessionState {
    /** Its parts are being started. */
    STARTING,
    /** Player, the tools and the spy run. */
    RUNNING,
    /** Player is gone for good (crashed, killed, or exited, and not restarted): nothing is served. */
    FAILED,
    /** Stopped on request (or after it failed): nothing of it runs. */
    CLOSED
}
