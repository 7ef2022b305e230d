package org.stagecraft.spy.hold;

import java.util.EnumMap;
import java.util.Map;
import java.util.stream.Collectors;

/**
 * A spy's robot hold at one moment.
 *
 * @param enabled     whether the user allowed holds for this spy (off: the relay is the plain byte copy)
 * @param held        whether the robots are held now: enabled and at least one reason holds
 * @param reasons     how many times each reason holds (a reason held twice needs two releases)
 * @param watchdogMillis the silence watchdog's timeout, 0 when it is off
 * @param epoch       counts the holds begun so far; a new hold has a new epoch
 */
public record HoldState(boolean enabled, boolean held, Map<HoldReason, Integer> reasons, long watchdogMillis, long epoch) {

    public HoldState {
        reasons = reasons.isEmpty() ? Map.of() : Map.copyOf(new EnumMap<>(reasons));
    }

    /**
     * One line for a status bar, e.g. "Robots held (suspended in the debugger): zero velocity sent,
     * motion commands held back".
     */
    public String description() {
        if (!enabled) {
            return "Robot holds off: the spy forwards every byte unchanged";
        }
        if (!held) {
            return "Robot holds armed" + (watchdogMillis > 0 ? " (silence watchdog " + watchdogMillis + " ms)" : "")
                    + ": nothing held";
        }
        String why = new EnumMap<>(reasons).keySet().stream().map(HoldReason::text).collect(Collectors.joining(", "));
        return "Robots held (" + why + "): zero velocity sent to Player, the program's motion commands held back";
    }
}
