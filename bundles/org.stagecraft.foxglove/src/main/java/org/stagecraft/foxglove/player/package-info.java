@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.foxglove.player;
