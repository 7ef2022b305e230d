package org.stagecraft.replay.export;

import java.util.ArrayDeque;
import java.util.Deque;

import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;

/**
 * A JSON Schema for the JSON {@link JsonBody} writes for one kind of message, generated from one
 * message's fields: integers, numbers, strings (base64 for opaque bytes), objects for structs,
 * arrays for lists with the first element's schema as their items (any item for an empty list).
 */
final class JsonSchemaOf implements FieldVisitor {
    private final StringBuilder b = new StringBuilder(1024);

    private static final class Frame {
        final boolean list;
        int members;

        Frame(boolean list) {
            this.list = list;
        }
    }

    private final Deque<Frame> open = new ArrayDeque<>();
    /** Depth inside a list element after the first, which is not described again. */
    private int skip;

    static String of(String title, MessageBody body) {
        JsonSchemaOf s = new JsonSchemaOf();
        s.b.append("{\"$schema\":\"https://json-schema.org/draft/2020-12/schema\",\"title\":");
        JsonText.string(s.b, title);
        s.b.append(",\"type\":\"object\",\"required\":[\"header\"],\"properties\":{\"header\":{\"type\":\"object\","
                + "\"properties\":{\"timestamp\":{\"type\":\"number\"},\"seq\":{\"type\":\"integer\"},"
                + "\"host\":{\"type\":\"integer\"},\"robot\":{\"type\":\"integer\"}}}");
        Frame root = new Frame(false);
        root.members = 1;
        s.open.push(root);
        body.describe(s);
        s.b.append("}}");
        return s.b.toString();
    }

    /** Starts a member; false when it is to be skipped (a list element after the first). */
    private boolean member(String name) {
        if (skip > 0) {
            return false;
        }
        Frame f = open.peek();
        if (f.list) {
            if (f.members++ > 0) {
                return false;
            }
            return true; // the items schema follows directly
        }
        if (f.members++ > 0) {
            b.append(',');
        }
        JsonText.string(b, name);
        b.append(':');
        return true;
    }

    private void leaf(String name, String type) {
        if (member(name)) {
            b.append("{\"type\":\"").append(type).append("\"}");
        }
    }

    @Override
    public void integer(String name, long value) {
        leaf(name, "integer");
    }

    @Override
    public void float32(String name, float value) {
        leaf(name, "number");
    }

    @Override
    public void float64(String name, double value) {
        leaf(name, "number");
    }

    @Override
    public void text(String name, String value) {
        leaf(name, "string");
    }

    @Override
    public void opaque(String name, byte[] value) {
        if (member(name)) {
            b.append("{\"type\":\"string\",\"contentEncoding\":\"base64\"}");
        }
    }

    @Override
    public void beginStruct(String name) {
        if (!member(name)) {
            skip++;
            return;
        }
        b.append("{\"type\":\"object\",\"properties\":{");
        open.push(new Frame(false));
    }

    @Override
    public void endStruct() {
        if (skip > 0) {
            skip--;
            return;
        }
        open.pop();
        b.append("}}");
    }

    @Override
    public void beginList(String name) {
        if (!member(name)) {
            skip++;
            return;
        }
        b.append("{\"type\":\"array\",\"items\":");
        open.push(new Frame(true));
    }

    @Override
    public void endList() {
        if (skip > 0) {
            skip--;
            return;
        }
        Frame f = open.pop();
        if (f.members == 0) {
            b.append("{}");
        }
        b.append('}');
    }
}
