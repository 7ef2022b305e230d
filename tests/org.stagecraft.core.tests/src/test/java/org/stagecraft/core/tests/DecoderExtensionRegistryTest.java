package org.stagecraft.core.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.junit.jupiter.api.Test;
import org.stagecraft.core.codec.DecoderExtensionRegistry;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.xdr.XdrWriter;

/** Decoders contributed by a plug-in through org.stagecraft.core.decoders, in a running OSGi runtime. */
class DecoderExtensionRegistryTest {

    private final List<IStatus> problems = new ArrayList<>();
    private final CodecRegistry registry = DecoderExtensionRegistry.load(Platform.getExtensionRegistry(), problems::add);

    @Test
    void contributedCodecDecodesItsInterface() {
        byte[] payload = new XdrWriter().float64(21.5).toByteArray();
        MessageHeader h = new MessageHeader(0, 6665, 300, 0, 1, 1, 3.0, 0, payload.length);
        DecodedMessage m = new PlayerDecoder(registry).decode(h, payload);
        assertEquals(new ThermometerCodec.Temperature(21.5), m.body());
        assertEquals("thermometer", registry.interfaceName(300));
        assertEquals("TEMPERATURE", registry.subtypeName(300, 1, 1));
    }

    @Test
    void declaredInterfaceNamesAreKnownAndStandardOnesRemain() {
        assertEquals("barometer", registry.interfaceName(301));
        assertEquals("laser", registry.interfaceName(6));
        assertEquals("GET_GEOM", registry.subtypeName(62, 3, 1));
    }

    @Test
    void brokenContributionsAreReportedByPluginAndSkipped() {
        assertEquals(2, problems.size(), problems.toString());
        assertTrue(problems.stream().allMatch(s -> s.getSeverity() == IStatus.ERROR));
        assertTrue(problems.stream().allMatch(s -> s.getMessage().contains("plug-in org.stagecraft.core.tests")),
                problems.toString());
        assertTrue(problems.stream().anyMatch(s -> s.getMessage().contains("<codec>")), problems.toString());
        assertTrue(problems.stream().anyMatch(s -> s.getMessage().contains("code 'lots' is not a number")),
                problems.toString());
    }
}
