package org.stagecraft.replay.fields;

import java.util.OptionalDouble;

import org.stagecraft.player.codec.MessageBody;

/** STAND-IN for the lead's FieldPath (replay-ui branch only; replaced by main's on merge). Dotted scalars only. */
public final class FieldPath {
    private final String text;

    private FieldPath(String text) {
        this.text = text;
    }

    public static FieldPath parse(String text) {
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("empty field path");
        }
        return new FieldPath(text.strip());
    }

    public OptionalDouble evaluate(MessageBody body) {
        FieldTree t = FieldTree.of(body);
        outer: for (String part : text.split("\\.")) {
            for (FieldTree c : t.children()) {
                if (c.name().equals(part)) {
                    t = c;
                    continue outer;
                }
            }
            return OptionalDouble.empty();
        }
        try {
            return t.children().isEmpty() ? OptionalDouble.of(Double.parseDouble(t.value())) : OptionalDouble.empty();
        } catch (NumberFormatException e) {
            return OptionalDouble.empty();
        }
    }

    @Override
    public String toString() {
        return text;
    }
}
