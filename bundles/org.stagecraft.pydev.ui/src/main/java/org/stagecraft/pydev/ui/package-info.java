@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.pydev.ui;
