package org.stagecraft.tools.session;

import java.time.Duration;
import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.spy.proxy.NetworkSpy;

/**
 * How a session's Network Spy treats robot programs, and what a hold does (docs/debugging-robots.md).
 *
 * @param upstreamGrace      how long a program's connection waits for Player to accept
 *                           ({@link NetworkSpy#upstreamGrace(Duration)})
 * @param holdWhenSuspended  hold the robots while the program is suspended in the debugger
 * @param watchdog           the silence watchdog's timeout, or null when it is off
 * @param freezeWorld        while the robots are held, freeze the simulated world too, when the session's Player
 *                           runs Stage (Stagecraft's world driver, {@link org.stagecraft.tools.world.WorldFreeze})
 */
public record SpyOptions(Duration upstreamGrace, boolean holdWhenSuspended, @Nullable Duration watchdog, boolean freezeWorld) {

    /** The defaults of a new launch configuration: hold when suspended, freeze the world, no watchdog, the spy's grace. */
    public static final SpyOptions DEFAULT = new SpyOptions(NetworkSpy.DEFAULT_UPSTREAM_GRACE, true, null, true);


    public SpyOptions {
        Objects.requireNonNull(upstreamGrace, "upstreamGrace");
        if (upstreamGrace.isNegative()) {
            throw new IllegalArgumentException("upstream grace " + upstreamGrace + " is negative");
        }
        // zero and negative mean "off", like RobotHold.setWatchdog; one spelling keeps equals meaningful
        watchdog = watchdog == null || watchdog.isZero() || watchdog.isNegative() ? null : watchdog;
    }

    /**
     * Whether the spy must make connections holdable. Any reason to hold enables holds, so the user's
     * emergency stop can hold every connection of such a session; a session with neither option set
     * keeps the plain byte copy, and an emergency stop cannot hold its programs' connections.
     */
    public boolean holdsEnabled() {
        return holdWhenSuspended || watchdog != null;
    }

    public SpyOptions withUpstreamGrace(Duration grace) {
        return new SpyOptions(grace, holdWhenSuspended, watchdog, freezeWorld);
    }

    public SpyOptions withHoldWhenSuspended(boolean on) {
        return new SpyOptions(upstreamGrace, on, watchdog, freezeWorld);
    }

    public SpyOptions withWatchdog(Duration timeout) {
        return new SpyOptions(upstreamGrace, holdWhenSuspended, timeout, freezeWorld);
    }

    public SpyOptions withFreezeWorld(boolean on) {
        return new SpyOptions(upstreamGrace, holdWhenSuspended, watchdog, on);
    }
}
