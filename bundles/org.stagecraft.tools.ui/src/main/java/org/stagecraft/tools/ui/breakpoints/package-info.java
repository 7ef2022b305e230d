/**
 * Robot data breakpoints in the workbench (docs/debugging-robots.md): the platform breakpoint type
 * (Breakpoints view, enable/disable, hit count, persisted with the workspace), its label, the commands that
 * add and edit one, and the wiring that gives a running Robot Session's spy the workbench's breakpoints and
 * suspends the robot program at a hit.
 */
@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.tools.ui.breakpoints;
