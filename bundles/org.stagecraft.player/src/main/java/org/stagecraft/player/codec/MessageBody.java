package org.stagecraft.player.codec;

import org.stagecraft.player.xdr.XdrWriter;

/** A decoded, immutable message payload that knows its XDR encoding and its Player field names. */
public interface MessageBody {

    /** Writes exactly the XDR bytes this body was decoded from. */
    void encode(XdrWriter out);

    /** Reports the fields, in wire order, by Player's names. */
    void describe(FieldVisitor visitor);
}
