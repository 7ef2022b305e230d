package org.stagecraft.spy.hold;

/**
 * The session's simulated world was frozen or thawed while its robots were held (docs/debugging-robots.md,
 * "The frozen world"). The spy only logs it ({@link org.stagecraft.spy.log.HoldEntry.Action#WORLD_FROZEN},
 * {@link org.stagecraft.spy.log.HoldEntry.Action#WORLD_THAWED}) and publishes it ({@link HoldStreams#WORLD}):
 * the session, which owns Player, does the freezing.
 *
 * @param frozen         whether the world stands still from now on
 * @param simTimeMicros  the simulated time the world stopped at or runs on from, in microseconds
 * @param text           for people, e.g. "world frozen at simulated time 12.300 s (suspended in the debugger)"
 */
public record WorldChange(boolean frozen, long simTimeMicros, String text) {
}
