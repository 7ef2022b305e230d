@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.spy.log;
