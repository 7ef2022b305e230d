package org.stagecraft.player.codec;

import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.xdr.XdrWriter;

/** Writes Player messages: the 40-byte header (its size set from the body) and the XDR body. */
public final class PlayerEncoder {
    private PlayerEncoder() {
    }

    public static byte[] encodeBody(MessageBody body) {
        XdrWriter w = new XdrWriter();
        body.encode(w);
        return w.toByteArray();
    }

    public static byte[] encode(MessageHeader header, MessageBody body) {
        byte[] payload = encodeBody(body);
        XdrWriter w = new XdrWriter(MessageHeader.SIZE + payload.length);
        header.withSize(payload.length).write(w);
        w.raw(payload, 0, payload.length);
        return w.toByteArray();
    }

    public static byte[] encode(DecodedMessage message) {
        return encode(message.header(), message.body());
    }
}
