package org.stagecraft.player.codec;

import org.stagecraft.player.xdr.XdrWriter;

/** A message without payload (size 0): most requests, ACKs, NACKs and SYNCH OK. */
public enum EmptyBody implements MessageBody {
    INSTANCE;

    @Override
    public void encode(XdrWriter out) {
        // nothing on the wire
    }

    @Override
    public void describe(FieldVisitor visitor) {
        // no fields
    }
}
