@org.eclipse.jdt.annotation.NonNullByDefault
package org.stagecraft.scene.shapes;
