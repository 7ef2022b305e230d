package org.stagecraft.player.msg;

import static org.stagecraft.player.wire.MessageType.REQ;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/** Requests every interface accepts (player.h): capabilities and typed properties. */
public final class Universal {
    private Universal() {
    }

    static void register(CodecRegistry r) {
        r.registerUniversal(REQ, 255, "CAPABILITIES", in -> new Capabilities(in.uint32(), in.uint32()));
        r.registerUniversal(REQ, 254, "GET_INTPROP", in -> IntProp.read(in));
        r.registerUniversal(REQ, 253, "SET_INTPROP", in -> IntProp.read(in));
        r.registerUniversal(REQ, 252, "GET_DBLPROP", in -> DblProp.read(in));
        r.registerUniversal(REQ, 251, "SET_DBLPROP", in -> DblProp.read(in));
        r.registerUniversal(REQ, 250, "GET_STRPROP", in -> StrProp.read(in));
        r.registerUniversal(REQ, 249, "SET_STRPROP", in -> StrProp.read(in));
        r.registerUniversal(REQ, 248, "GET_BOOLPROP", in -> BoolProp.read(in));
        r.registerUniversal(REQ, 247, "SET_BOOLPROP", in -> BoolProp.read(in));
    }

    /** player_capabilities_req: does the device support (type, subtype)? */
    public record Capabilities(int type, int subtype) implements MessageBody {
        @Override
        public void encode(XdrWriter w) {
            w.uint32(type).uint32(subtype);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "type", type);
            Xdr.u32(v, "subtype", subtype);
        }
    }

    /** player_intprop_req. */
    public record IntProp(int keyCount, ByteArray key, int value) implements MessageBody {
        static IntProp read(XdrReader r) {
            return new IntProp(r.uint32(), Xdr.bytes(r), r.int32());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(keyCount);
            Xdr.bytes(w, key);
            w.int32(value);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "key_count", keyCount);
            Xdr.text(v, "key", key);
            v.integer("value", value);
        }
    }

    /** player_dblprop_req. */
    public record DblProp(int keyCount, ByteArray key, double value) implements MessageBody {
        static DblProp read(XdrReader r) {
            return new DblProp(r.uint32(), Xdr.bytes(r), r.float64());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(keyCount);
            Xdr.bytes(w, key);
            w.float64(value);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "key_count", keyCount);
            Xdr.text(v, "key", key);
            v.float64("value", value);
        }
    }

    /** player_strprop_req. */
    public record StrProp(int keyCount, ByteArray key, int valueCount, ByteArray value) implements MessageBody {
        static StrProp read(XdrReader r) {
            return new StrProp(r.uint32(), Xdr.bytes(r), r.uint32(), Xdr.bytes(r));
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(keyCount);
            Xdr.bytes(w, key);
            w.uint32(valueCount);
            Xdr.bytes(w, value);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "key_count", keyCount);
            Xdr.text(v, "key", key);
            Xdr.u32(v, "value_count", valueCount);
            Xdr.text(v, "value", value);
        }
    }

    /** player_boolprop_req: the value is a char on the wire. */
    public record BoolProp(int keyCount, ByteArray key, int value) implements MessageBody {
        static BoolProp read(XdrReader r) {
            return new BoolProp(r.uint32(), Xdr.bytes(r), r.int8());
        }

        @Override
        public void encode(XdrWriter w) {
            w.uint32(keyCount);
            Xdr.bytes(w, key);
            w.int8(value);
        }

        @Override
        public void describe(FieldVisitor v) {
            Xdr.u32(v, "key_count", keyCount);
            Xdr.text(v, "key", key);
            v.integer("value", value);
        }
    }
}
