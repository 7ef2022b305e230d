package org.stagecraft.replay.fields;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

import org.stagecraft.player.codec.MessageBody;

/**
 * A body's leaf fields by dotted path ({@code pos.px}, {@code ranges[0]}, {@code poses[2].px}), in
 * wire order: one column per leaf for CSV, one line per leaf for text views. Paths are the syntax
 * {@link FieldPath} reads.
 */
public final class FlatFields {
    private FlatFields() {
    }

    /**
     * @return path to value: {@link Long}, {@link Float}, {@link Double}, {@link String} or {@code byte[]}
     */
    public static Map<String, Object> flatten(MessageBody body) {
        Map<String, Object> out = new LinkedHashMap<>();
        for (Field f : FieldTree.of(body).children()) {
            walk(Objects.requireNonNull(f.name()), f, out); // the body's own fields have names
        }
        return out;
    }

    /** Leaf paths under {@code field}, which sits at {@code path}. */
    static void walk(String path, Field field, Map<String, Object> out) {
        switch (field.kind()) {
            case STRUCT -> {
                for (Field c : field.children()) {
                    walk(path + "." + c.name(), c, out);
                }
            }
            case LIST -> {
                int i = 0;
                for (Field c : field.children()) {
                    walk(path + "[" + i++ + "]", c, out);
                }
            }
            default -> out.put(path, Objects.requireNonNull(field.value())); // a leaf has a value
        }
    }
}
