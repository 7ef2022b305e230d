package org.stagecraft.replay.fields;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;

/**
 * Builds the field tree of a decoded body from what the body reports through {@link FieldVisitor},
 * so the inspector, plots and exports see every message kind the same way, including kinds that
 * plug-ins add.
 */
public final class FieldTree implements FieldVisitor {
    /** Name of the root struct that holds a body's top-level fields. */
    public static final String ROOT = "body";

    private record Open(@Nullable String name, Field.Kind kind, List<Field> children) {
    }

    private final Deque<Open> open = new ArrayDeque<>();

    private FieldTree() {
        open.push(new Open(ROOT, Field.Kind.STRUCT, new ArrayList<>()));
    }

    /** The body's fields as a struct named {@value #ROOT}. */
    public static Field of(MessageBody body) {
        FieldTree t = new FieldTree();
        body.describe(t);
        if (t.open.size() != 1) {
            throw new IllegalStateException(body.getClass().getName() + " reports unbalanced structs or lists");
        }
        Open root = t.open.pop();
        return new Field(root.name(), root.kind(), null, root.children());
    }

    private void add(@Nullable String name, Field.Kind kind, Object value) {
        open.peek().children().add(new Field(name, kind, value, List.of()));
    }

    @Override
    public void integer(@Nullable String name, long value) {
        add(name, Field.Kind.INTEGER, value);
    }

    @Override
    public void float32(@Nullable String name, float value) {
        add(name, Field.Kind.FLOAT32, value);
    }

    @Override
    public void float64(@Nullable String name, double value) {
        add(name, Field.Kind.FLOAT64, value);
    }

    @Override
    public void text(@Nullable String name, String value) {
        add(name, Field.Kind.TEXT, value);
    }

    @Override
    public void opaque(@Nullable String name, byte[] value) {
        add(name, Field.Kind.OPAQUE, value.clone());
    }

    @Override
    public void beginStruct(@Nullable String name) {
        open.push(new Open(name, Field.Kind.STRUCT, new ArrayList<>()));
    }

    @Override
    public void endStruct() {
        close(Field.Kind.STRUCT);
    }

    @Override
    public void beginList(@Nullable String name) {
        open.push(new Open(name, Field.Kind.LIST, new ArrayList<>()));
    }

    @Override
    public void endList() {
        close(Field.Kind.LIST);
    }

    private void close(Field.Kind kind) {
        if (open.size() < 2 || open.peek().kind() != kind) {
            throw new IllegalStateException("end of " + kind + " without its beginning");
        }
        Open o = open.pop();
        open.peek().children().add(new Field(o.name(), o.kind(), null, o.children()));
    }
}
