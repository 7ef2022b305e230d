package org.stagecraft.player.codec;

import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.player.xdr.XdrException;
import org.stagecraft.player.xdr.XdrReader;

/**
 * Turns framed Player messages into typed bodies. Never throws: a payload no decoder is
 * registered for stays a {@link RawBody}; a payload a decoder cannot read (or a decoder that
 * fails) also stays raw and carries a {@link DecodeProblem}. Thread-safe.
 */
public final class PlayerDecoder {
    private final CodecRegistry registry;

    public PlayerDecoder(CodecRegistry registry) {
        this.registry = registry;
    }

    public CodecRegistry registry() {
        return registry;
    }

    public DecodedMessage decode(WireEvent.Frame frame) {
        return decode(frame.header(), frame.payloadUnsafe());
    }

    /** Decodes a payload; the array is read, never kept or changed. */
    public DecodedMessage decode(MessageHeader header, byte[] payload) {
        if (payload.length == 0) {
            return new DecodedMessage(header, EmptyBody.INSTANCE, null);
        }
        CodecRegistry.Layout layout = registry.lookup(header.interf(), header.type(), header.subtype());
        if (layout == null) {
            return new DecodedMessage(header, new RawBody(payload), null);
        }
        XdrReader in = new XdrReader(payload);
        try {
            MessageBody body = layout.decoder().decode(in);
            in.expectEnd();
            return new DecodedMessage(header, body, null);
        } catch (XdrException e) {
            return new DecodedMessage(header, new RawBody(payload), new DecodeProblem(e.offset(),
                    describe(header, layout) + ": " + e.getMessage()));
        } catch (RuntimeException | StackOverflowError e) {
            return new DecodedMessage(header, new RawBody(payload), new DecodeProblem(in.position(),
                    describe(header, layout) + ": decoder failed with " + e));
        }
    }

    private String describe(MessageHeader h, CodecRegistry.Layout layout) {
        String iface = registry.interfaceName(h.interf());
        return (iface != null ? iface : "interface " + h.interf()) + " " + layout.subtypeName() + " payload of "
                + h.size() + " bytes does not fit its layout";
    }
}
