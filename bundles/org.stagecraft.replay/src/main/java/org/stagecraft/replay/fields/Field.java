package org.stagecraft.replay.fields;

import java.util.List;

import org.eclipse.jdt.annotation.Nullable;

/**
 * One field of a decoded Player message, named as in Player's interface definitions. Lists hold
 * unnamed elements (their name is null; paths address them by index).
 *
 * @param name     the field's name, null for a list element
 * @param kind     what the value is
 * @param value    a {@link Long} for integers, {@link Float} for float32, {@link Double} for float64,
 *                 a {@link String} for text, a {@code byte[]} for opaque bytes; null for structs and lists
 * @param children the members of a struct or the elements of a list, in wire order; empty otherwise
 */
public record Field(@Nullable String name, Kind kind, @Nullable Object value, List<Field> children) {

    /** The kinds of field the codec reports. */
    public enum Kind {
        INTEGER, FLOAT32, FLOAT64, TEXT, OPAQUE, STRUCT, LIST;

        public boolean numeric() {
            return this == INTEGER || this == FLOAT32 || this == FLOAT64;
        }
    }

    public Field {
        children = List.copyOf(children);
    }

    /** The value as a double, for numeric fields. */
    public double number() {
        if (!kind.numeric()) {
            throw new IllegalStateException((name == null ? "element" : name) + " is " + kind + ", not a number");
        }
        return ((Number) value).doubleValue();
    }

    /** The member of a struct with this name, or null. */
    public @Nullable Field member(String memberName) {
        for (Field c : children) {
            if (memberName.equals(c.name())) {
                return c;
            }
        }
        return null;
    }
}
