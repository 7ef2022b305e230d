package org.stagecraft.player.msg;

import org.stagecraft.player.codec.BodyDecoder;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.xdr.XdrWriter;

/** Structs of one scalar member (power switches, modes, ids), which many interfaces define. */
public final class Scalar {
    private Scalar() {
    }

    /** A struct whose only member is a uint8_t, e.g. {@code state} of a power config. */
    public record Uint8(String name, int value) implements MessageBody {
        static BodyDecoder decoder(String name) {
            return in -> new Uint8(name, in.uint8());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint8(value);
        }

        @Override
        public void describe(FieldVisitor v) {
            v.integer(name, value);
        }
    }

    /** A struct whose only member is a uint32_t, e.g. a mode or an id. */
    public record Uint32(String name, int value) implements MessageBody {
        static BodyDecoder decoder(String name) {
            return in -> new Uint32(name, in.uint32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(value);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, name, value);
        }
    }
}
