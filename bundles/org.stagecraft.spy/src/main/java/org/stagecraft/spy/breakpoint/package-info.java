/**
 * Robot data breakpoints (docs/debugging-robots.md): a condition over what Player sends a robot
 * program; when a message satisfies it, the spy holds that message and everything after it back from the
 * program, holds the robots and tells its listeners (the IDE suspends the program), then passes the
 * messages on.
 */
@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.spy.breakpoint;
