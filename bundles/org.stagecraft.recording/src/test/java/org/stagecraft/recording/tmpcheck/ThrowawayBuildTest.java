package org.stagecraft.recording.tmpcheck;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

class ThrowawayBuildTest {
    @Test
    void seesRequiredBundleAndImportedPackages() throws Exception {
        assertNotNull(Class.forName("org.stagecraft.player.xdr.XdrReader"));
        assertEquals("{\"a\":1}", new com.google.gson.Gson().toJson(java.util.Map.of("a", 1)));
        assertNotNull(new com.google.gson.stream.JsonReader(new java.io.StringReader("{}")));
        System.out.println("CP=" + System.getProperty("java.class.path"));
    }
}
