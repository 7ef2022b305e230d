package org.stagecraft.player.codec;

import org.stagecraft.player.xdr.XdrWriter;

/** A payload kept as the bytes it arrived as: no decoder is registered, or the decoder refused it. */
public final class RawBody implements MessageBody {
    private final byte[] bytes;

    public RawBody(byte[] bytes) {
        this.bytes = bytes.clone();
    }

    public byte[] bytes() {
        return bytes.clone();
    }

    public int length() {
        return bytes.length;
    }

    @Override
    public void encode(XdrWriter out) {
        out.raw(bytes, 0, bytes.length);
    }

    @Override
    public void describe(FieldVisitor visitor) {
        visitor.opaque("raw", bytes);
    }
}
