package org.stagecraft.tools.tests;

/** Contributed as a tool type by mistake (plugin.xml): must be reported, not loaded. */
public final class NotAToolType {
}
