package org.stagecraft.player.msg;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.xdr.XdrReader;
import org.stagecraft.player.xdr.XdrWriter;

/**
 * The array and string encodings of Player's XDR generator (playerxdrgen.py), shared by the
 * message classes. A member {@code T foo[]} with a sibling {@code foo_count} is written as the
 * count member, then xdr_array's own element count, then the elements; byte arrays use xdr_bytes.
 */
final class Xdr {
    private Xdr() {
    }

    static FloatArray floats(XdrReader r) {
        int n = r.count(4);
        return FloatArray.adopt(r.float32Array(n));
    }

    static void floats(XdrWriter w, FloatArray a) {
        w.int32(a.size());
        for (float f : a.raw()) {
            w.float32(f);
        }
    }

    static DoubleArray doubles(XdrReader r) {
        int n = r.count(8);
        return DoubleArray.adopt(r.float64Array(n));
    }

    static void doubles(XdrWriter w, DoubleArray a) {
        w.int32(a.size());
        for (double d : a.raw()) {
            w.float64(d);
        }
    }

    static ByteArray bytes(XdrReader r) {
        return ByteArray.adopt(r.bytes());
    }

    static void bytes(XdrWriter w, ByteArray a) {
        w.bytes(a.raw());
    }

    static <T> List<T> structs(XdrReader r, int minElementBytes, Function<XdrReader, T> element) {
        int n = r.count(minElementBytes);
        List<T> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            out.add(element.apply(r));
        }
        return List.copyOf(out);
    }

    static void structs(XdrWriter w, List<? extends MessageBody> list) {
        w.int32(list.size());
        for (MessageBody b : list) {
            b.encode(w);
        }
    }

    // ---- describing -------------------------------------------------------------------------

    static void u32(FieldVisitor v, String name, int value) {
        v.integer(name, Integer.toUnsignedLong(value));
    }

    static void floats(FieldVisitor v, String name, FloatArray a) {
        v.beginList(name);
        for (float f : a.raw()) {
            v.float32(null, f);
        }
        v.endList();
    }

    static void doubles(FieldVisitor v, String name, DoubleArray a) {
        v.beginList(name);
        for (double d : a.raw()) {
            v.float64(null, d);
        }
        v.endList();
    }

    /** A uint8 array with numeric meaning (intensities, bumper states). */
    static void uint8s(FieldVisitor v, String name, ByteArray a) {
        v.beginList(name);
        for (byte b : a.raw()) {
            v.integer(null, b & 0xFF);
        }
        v.endList();
    }

    static void text(FieldVisitor v, String name, ByteArray a) {
        v.text(name, a.text());
    }

    static void struct(FieldVisitor v, String name, MessageBody b) {
        v.beginStruct(name);
        b.describe(v);
        v.endStruct();
    }

    static void structs(FieldVisitor v, String name, List<? extends MessageBody> list) {
        v.beginList(name);
        for (MessageBody b : list) {
            v.beginStruct(null);
            b.describe(v);
            v.endStruct();
        }
        v.endList();
    }
}
