package org.stagecraft.player.codec;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** Collects a body's fields into nested maps and lists, for assertions. */
public final class Fields implements FieldVisitor {
    private final Deque<Object> stack = new ArrayDeque<>();

    private Fields() {
        stack.push(new LinkedHashMap<String, Object>());
    }

    public static Map<String, Object> of(MessageBody body) {
        Fields f = new Fields();
        body.describe(f);
        @SuppressWarnings("unchecked")
        Map<String, Object> root = (Map<String, Object>) f.stack.peek();
        return root;
    }

    @SuppressWarnings("unchecked")
    private void put(String name, Object value) {
        Object top = stack.peek();
        if (top instanceof Map<?, ?> m) {
            ((Map<String, Object>) m).put(name, value);
        } else {
            ((List<Object>) top).add(value);
        }
    }

    @Override
    public void integer(String name, long value) {
        put(name, value);
    }

    @Override
    public void float32(String name, float value) {
        put(name, value);
    }

    @Override
    public void float64(String name, double value) {
        put(name, value);
    }

    @Override
    public void text(String name, String value) {
        put(name, value);
    }

    @Override
    public void opaque(String name, byte[] value) {
        put(name, value);
    }

    @Override
    public void beginStruct(String name) {
        Map<String, Object> m = new LinkedHashMap<>();
        put(name, m);
        stack.push(m);
    }

    @Override
    public void endStruct() {
        stack.pop();
    }

    @Override
    public void beginList(String name) {
        List<Object> l = new ArrayList<>();
        put(name, l);
        stack.push(l);
    }

    @Override
    public void endList() {
        stack.pop();
    }
}
