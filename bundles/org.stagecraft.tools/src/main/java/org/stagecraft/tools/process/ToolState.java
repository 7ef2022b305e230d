package org.stagecraft.tools.process;

/** Where a supervised tool is in its life. */
public enum ToolState {
    /** Not started yet. */
    NEW,
    /** The process runs; waiting for its readiness check. */
    STARTING,
    /** Running and ready. */
    READY,
    /** It ended by itself; the restart policy starts it again. */
    RESTARTING,
    /** Being stopped on request. */
    STOPPING,
    /** Stopped on request (the whole process tree is gone). */
    STOPPED,
    /** It ended by itself with exit code 0 and the policy does not restart it. */
    EXITED,
    /** It crashed or never became ready, and the policy does not (or no longer) restart it. */
    FAILED;

    /** Whether no process of the tool runs any more, and none will be started. */
    public boolean isFinal() {
        return this == STOPPED || this == EXITED || this == FAILED;
    }
}
