package org.stagecraft.spy.log;

import java.nio.charset.StandardCharsets;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.mcap.RecordBuffer;
import org.stagecraft.mcap.RecordInput;
import org.stagecraft.mcap.McapFormatException;

/**
 * The protobuf encoding of the spy log's binary channels (wire and hold messages), written by hand:
 * two small messages do not justify protobuf-java in the spy. The schema the log declares for them
 * ({@link #DESCRIPTOR_SET}, a {@code google.protobuf.FileDescriptorSet}) lets MCAP tools that know
 * protobuf ({@code mcap cat --json}, Foxglove) decode them without knowing Stagecraft:
 *
 * <pre>
 * syntax = "proto3";
 * package stagecraft.spy;
 * message WireMessage {            // one framer event of a stream
 *   enum Kind { KIND_UNSPECIFIED = 0; BANNER = 1; FRAME = 2; UNFRAMED = 3; }
 *   uint64 offset = 1;             // stream offset of the first byte
 *   Kind kind = 2;
 *   string reason = 3;             // why the bytes are unframed
 *   bytes wire = 4;                // the exact wire bytes (written last)
 * }
 * message HoldAction {             // one thing a robot hold did
 *   enum Action { ACTION_UNSPECIFIED = 0; INJECTED = 1; HELD_BACK = 2; HOLD_ON = 3; HOLD_OFF = 4; BREAK = 5; PASSED_ON = 6; WORLD_FROZEN = 7; WORLD_THAWED = 8; }
 *   uint32 conn = 1; uint32 port = 2; Action action = 3;
 *   uint64 program_offset = 4; uint64 upstream_offset = 5; string text = 6; bytes bytes = 7;
 * }
 * </pre>
 */
final class WireProto {
    private WireProto() {
    }

    static final String WIRE_MESSAGE = "stagecraft.spy.WireMessage";
    static final String HOLD_ACTION = "stagecraft.spy.HoldAction";

    private static final int VARINT = 0;
    private static final int LEN = 2;

    static final byte[] DESCRIPTOR_SET = descriptorSet();

    // --- encoding --------------------------------------------------------------------------------

    static void varint(RecordBuffer b, long v) {
        while ((v & ~0x7FL) != 0) {
            b.u8((int) ((v & 0x7F) | 0x80));
            v >>>= 7;
        }
        b.u8((int) v);
    }

    static void tag(RecordBuffer b, int field, int wireType) {
        varint(b, (long) field << 3 | wireType);
    }

    static void uint(RecordBuffer b, int field, long v) {
        tag(b, field, VARINT);
        varint(b, v);
    }

    static void bytes(RecordBuffer b, int field, byte[] data, int off, int len) {
        tag(b, field, LEN);
        varint(b, len);
        b.bytes(data, off, len);
    }

    static void string(RecordBuffer b, int field, String s) {
        byte[] u = s.getBytes(StandardCharsets.UTF_8);
        bytes(b, field, u, 0, u.length);
    }

    // --- decoding --------------------------------------------------------------------------------

    /** Receives the fields of one message. */
    interface FieldVisitor {
        void varint(int field, long value) throws McapFormatException;

        void bytes(int field, byte[] array, int offset, int length) throws McapFormatException;
    }

    static void read(RecordInput in, FieldVisitor v) throws McapFormatException {
        byte[] a = in.array();
        while (in.remaining() > 0) {
            long key = readVarint(in);
            int field = (int) (key >>> 3);
            switch ((int) (key & 7)) {
                case VARINT -> v.varint(field, readVarint(in));
                case LEN -> {
                    long n = readVarint(in);
                    if (n < 0 || n > in.remaining()) {
                        throw new McapFormatException("protobuf field " + field + " runs past its message");
                    }
                    int at = in.pos();
                    in.skip((int) n);
                    v.bytes(field, a, at, (int) n);
                }
                case 1 -> in.skip(8);
                case 5 -> in.skip(4);
                default -> throw new McapFormatException("protobuf wire type " + (key & 7) + " is not supported");
            }
        }
    }

    private static long readVarint(RecordInput in) throws McapFormatException {
        long v = 0;
        for (int shift = 0; shift < 64; shift += 7) {
            int b = in.u8();
            v |= (long) (b & 0x7F) << shift;
            if ((b & 0x80) == 0) {
                return v;
            }
        }
        throw new McapFormatException("protobuf varint longer than 10 bytes");
    }

    // --- the schema ------------------------------------------------------------------------------

    private static final int TYPE_UINT64 = 4;
    private static final int TYPE_STRING = 9;
    private static final int TYPE_BYTES = 12;
    private static final int TYPE_UINT32 = 13;
    private static final int TYPE_ENUM = 14;

    /** FileDescriptorSet { file: FileDescriptorProto } for stagecraft/spy.proto. */
    private static byte[] descriptorSet() {
        RecordBuffer wire = message("WireMessage",
                enumType("Kind", "KIND_UNSPECIFIED", "BANNER", "FRAME", "UNFRAMED"),
                field("offset", 1, TYPE_UINT64, null), field("kind", 2, TYPE_ENUM, ".stagecraft.spy.WireMessage.Kind"),
                field("reason", 3, TYPE_STRING, null), field("wire", 4, TYPE_BYTES, null));
        RecordBuffer hold = message("HoldAction",
                enumType("Action", "ACTION_UNSPECIFIED", "INJECTED", "HELD_BACK", "HOLD_ON", "HOLD_OFF", "BREAK", "PASSED_ON", "WORLD_FROZEN", "WORLD_THAWED"),
                field("conn", 1, TYPE_UINT32, null), field("port", 2, TYPE_UINT32, null),
                field("action", 3, TYPE_ENUM, ".stagecraft.spy.HoldAction.Action"),
                field("program_offset", 4, TYPE_UINT64, null), field("upstream_offset", 5, TYPE_UINT64, null),
                field("text", 6, TYPE_STRING, null), field("bytes", 7, TYPE_BYTES, null));
        RecordBuffer file = new RecordBuffer(512);
        string(file, 1, "stagecraft/spy.proto");
        string(file, 2, "stagecraft.spy");
        bytes(file, 4, wire.array(), 0, wire.size());
        bytes(file, 4, hold.array(), 0, hold.size());
        string(file, 12, "proto3");
        RecordBuffer set = new RecordBuffer(512);
        bytes(set, 1, file.array(), 0, file.size());
        return set.toByteArray();
    }

    /** DescriptorProto: name 1, field 2, enum_type 4. */
    private static RecordBuffer message(String name, RecordBuffer enumType, RecordBuffer... fields) {
        RecordBuffer m = new RecordBuffer(256);
        string(m, 1, name);
        for (RecordBuffer f : fields) {
            bytes(m, 2, f.array(), 0, f.size());
        }
        bytes(m, 4, enumType.array(), 0, enumType.size());
        return m;
    }

    /** FieldDescriptorProto: name 1, number 3, label 4 (optional), type 5, type_name 6. */
    private static RecordBuffer field(String name, int number, int type, @Nullable String typeName) {
        RecordBuffer f = new RecordBuffer(64);
        string(f, 1, name);
        uint(f, 3, number);
        uint(f, 4, 1);
        uint(f, 5, type);
        if (typeName != null) {
            string(f, 6, typeName);
        }
        return f;
    }

    /** EnumDescriptorProto: name 1, value 2 (EnumValueDescriptorProto: name 1, number 2), numbered from 0. */
    private static RecordBuffer enumType(String name, String... values) {
        RecordBuffer e = new RecordBuffer(128);
        string(e, 1, name);
        for (int i = 0; i < values.length; i++) {
            RecordBuffer v = new RecordBuffer(32);
            string(v, 1, values[i]);
            uint(v, 2, i);
            bytes(e, 2, v.array(), 0, v.size());
        }
        return e;
    }
}
