package org.stagecraft.spy.breakpoint;

/**
 * Told what robot data breakpoints do. Called on the relay thread that found the hit (which waits, with
 * the triggering message, until {@link BreakpointHit#passOn()} or the bound): return quickly.
 */
public interface BreakpointListener {
    /** A breakpoint's condition held: the robots are held, the message waits. */
    void hit(BreakpointHit hit);

    /** The held-back messages went on to the program ({@link BreakpointHit#passedOnWhy()} says why). */
    default void passedOn(BreakpointHit hit) {
    }

    /** The hit ended ({@link DataBreakpoints#resume()}): the robots move again, breakpoints are tested again. */
    default void resumed(BreakpointHit hit) {
    }
}
