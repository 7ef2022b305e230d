package org.stagecraft.player.codec;

import org.stagecraft.player.wire.MessageType;

/** Registered through META-INF/services, the plain-Java way (no OSGi). */
public final class ServiceLoadedContribution implements CodecContribution {
    @Override
    public void contributeTo(CodecRegistry registry) {
        registry.registerInterface(400, "odometer");
        registry.register(400, MessageType.DATA, 1, "DISTANCE", in -> new RawBody(in.opaque(8)));
    }
}
