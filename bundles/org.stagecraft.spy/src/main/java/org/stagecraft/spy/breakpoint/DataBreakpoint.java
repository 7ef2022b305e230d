package org.stagecraft.spy.breakpoint;

import java.util.Objects;

/**
 * One robot data breakpoint as set by the user.
 *
 * @param id        names it for its owner (the IDE: the marker's id; the command line: its --break)
 * @param condition what a message from Player must satisfy
 * @param enabled   a disabled breakpoint is not tested
 * @param hitCount  0: stop on every message that satisfies the condition; N: stop on the Nth only, after
 *                  which the breakpoint disables itself (Eclipse's hit count)
 */
public record DataBreakpoint(String id, MessageCondition condition, boolean enabled, int hitCount) {

    public DataBreakpoint {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(condition, "condition");
        if (hitCount < 0) {
            throw new IllegalArgumentException("hit count " + hitCount + " is negative");
        }
    }

    public DataBreakpoint(String id, MessageCondition condition) {
        this(id, condition, true, 0);
    }

    public String text() {
        return condition.text();
    }
}
