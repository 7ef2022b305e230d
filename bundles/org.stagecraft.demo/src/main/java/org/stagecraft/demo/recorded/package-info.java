@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.demo.recorded;
