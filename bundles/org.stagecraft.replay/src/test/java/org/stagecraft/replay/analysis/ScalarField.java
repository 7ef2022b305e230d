package org.stagecraft.replay.analysis;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.OptionalDouble;

import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;

/** A dotted scalar field of a body ("pos.px"), found by walking its fields: the tests' own value function. */
final class ScalarField implements FieldVisitor {
    private final String path;
    private final Deque<String> names = new ArrayDeque<>();
    private int lists;
    private Double found;

    private ScalarField(String path) {
        this.path = path;
    }

    static OptionalDouble of(MessageBody body, String path) {
        ScalarField f = new ScalarField(path);
        body.describe(f);
        return f.found == null ? OptionalDouble.empty() : OptionalDouble.of(f.found);
    }

    private void number(String name, double v) {
        if (lists == 0 && found == null && name != null) {
            StringBuilder p = new StringBuilder();
            names.descendingIterator().forEachRemaining(n -> p.append(n).append('.'));
            if (p.append(name).toString().equals(path)) {
                found = v;
            }
        }
    }

    @Override
    public void integer(String name, long value) {
        number(name, value);
    }

    @Override
    public void float32(String name, float value) {
        number(name, value);
    }

    @Override
    public void float64(String name, double value) {
        number(name, value);
    }

    @Override
    public void text(String name, String value) {
    }

    @Override
    public void opaque(String name, byte[] value) {
    }

    @Override
    public void beginStruct(String name) {
        names.push(String.valueOf(name));
    }

    @Override
    public void endStruct() {
        names.pop();
    }

    @Override
    public void beginList(String name) {
        lists++;
        names.push(String.valueOf(name));
    }

    @Override
    public void endList() {
        lists--;
        names.pop();
    }
}
