@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.core.codec;
