@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.tools.ui.console;
