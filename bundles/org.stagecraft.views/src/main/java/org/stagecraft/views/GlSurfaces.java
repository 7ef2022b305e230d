package org.stagecraft.views;

import org.eclipse.jdt.annotation.Nullable;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;

import com.jogamp.opengl.GLCapabilities;
import com.jogamp.opengl.GLProfile;
import com.jogamp.opengl.swt.GLCanvas;

/**
 * Creates the GL canvases of Robot Views: JOGL's SWT GLCanvas with a compatibility (GL2) profile,
 * 8 bits per colour channel (pixel tests depend on exact 8-bit blending; Mesa would otherwise be free to
 * pick a 10-bit visual), double buffered.
 */
public final class GlSurfaces {
    private static @Nullable GLProfile profile;

    private GlSurfaces() {
    }

    /** The GL2 profile; initialises JOGL (loads its natives) on first use. */
    public static synchronized GLProfile profile() {
        GLProfile p = profile;
        if (p == null) {
            GLProfile.initSingleton();
            p = GLProfile.get(GLProfile.GL2);
            profile = p;
        }
        return p;
    }

    public static GLCapabilities capabilities() {
        GLCapabilities caps = new GLCapabilities(profile());
        caps.setRedBits(8);
        caps.setGreenBits(8);
        caps.setBlueBits(8);
        caps.setAlphaBits(0);
        caps.setDepthBits(0);
        caps.setDoubleBuffered(true);
        return caps;
    }

    public static GLCanvas create(Composite parent) {
        return new GLCanvas(parent, SWT.NO_BACKGROUND, capabilities(), null);
    }
}
