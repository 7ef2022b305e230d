package org.stagecraft.spy.hold;

/** Why Stagecraft holds the robots. Reasons are counted: the hold is on while any reason holds. */
public enum HoldReason {
    /** The robot program stopped in the debugger (breakpoint, step, suspend). */
    SUSPENDED("suspended in the debugger"),
    /** The user pressed the emergency stop. */
    EMERGENCY_STOP("emergency stop"),
    /** The robot program went silent while its robot was moving. */
    WATCHDOG("program silent while moving"),
    /** A robot data breakpoint's condition held on a message from Player (docs/debugging-robots.md). */
    DATA_BREAKPOINT("robot data breakpoint");

    private final String text;

    HoldReason(String text) {
        this.text = text;
    }

    /** For people, e.g. in a status line. */
    public String text() {
        return text;
    }
}
