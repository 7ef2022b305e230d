/**
 * The frozen world (docs/debugging-robots.md): Stagecraft's own Player driver that stops and restarts the
 * Stage world of a session's Player ({@link org.stagecraft.tools.world.WorldDriver}, built from its C++
 * source on first use), the channel to it ({@link org.stagecraft.tools.world.WorldChannel}), and the part
 * that freezes the world while the session's robots are held ({@link org.stagecraft.tools.world.WorldFreeze}).
 */
@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.tools.world;
