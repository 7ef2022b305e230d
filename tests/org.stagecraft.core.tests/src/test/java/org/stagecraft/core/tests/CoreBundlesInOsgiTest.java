package org.stagecraft.core.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkUtil;

/** The Stagecraft bundles resolve and start in a real OSGi runtime (Equinox), with the Eclipse runtime. */
class CoreBundlesInOsgiTest {

    private static Bundle bundle(String symbolicName) {
        BundleContext context = FrameworkUtil.getBundle(CoreBundlesInOsgiTest.class).getBundleContext();
        assertNotNull(context, "test bundle has no context (not started?)");
        return Arrays.stream(context.getBundles())
                .filter(b -> symbolicName.equals(b.getSymbolicName()))
                .findFirst()
                .orElseThrow(() -> new AssertionError(symbolicName + " is not installed in the test runtime"));
    }

    private static boolean resolved(Bundle b) {
        return (b.getState() & (Bundle.RESOLVED | Bundle.STARTING | Bundle.ACTIVE)) != 0;
    }

    @Test
    void playerBundleIsResolved() {
        Bundle player = bundle("org.stagecraft.player");
        assertTrue(resolved(player), "org.stagecraft.player state " + player.getState());
    }

    @Test
    void streamsBundleIsResolved() {
        Bundle streams = bundle("org.stagecraft.streams");
        assertTrue(resolved(streams), "org.stagecraft.streams state " + streams.getState());
    }

    @Test
    void coreBundleIsActive() throws Exception {
        Bundle core = bundle("org.stagecraft.core");
        assertTrue(resolved(core), "org.stagecraft.core state " + core.getState());
        if (core.getState() != Bundle.ACTIVE) {
            core.start(Bundle.START_TRANSIENT); // lazy activation: no class of it loaded yet
        }
        assertEquals(Bundle.ACTIVE, core.getState(), "org.stagecraft.core is not active");
    }

    @Test
    void eclipseRuntimeIsActive() {
        assertEquals(Bundle.ACTIVE, bundle("org.eclipse.core.runtime").getState());
    }
}
