package org.stagecraft.player.json;

import java.util.ArrayDeque;
import java.util.Base64;
import java.util.Deque;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;

/**
 * Writes a decoded body's fields as JSON members, by Player's names: integers as they are, numbers
 * as {@link JsonNumbers} says, text escaped by {@link JsonText}, opaque bytes in base64, structs as
 * objects and lists as arrays. The one JSON writer of decoded messages: the MCAP export's Player
 * channels ({@link JsonNumbers#SCHEMA}) and the command line's {@code decode} ({@link JsonNumbers#LOSSLESS}).
 */
public final class JsonFieldWriter implements FieldVisitor {
    private final StringBuilder b;
    private final JsonNumbers numbers;
    /** Per open object or array: whether something was written in it yet. */
    private final Deque<boolean[]> open = new ArrayDeque<>();

    /**
     * Writes into an object (or array) already open in {@code b}; {@code hasMembers} says whether it
     * holds something already (then the first field is preceded by a comma).
     */
    public JsonFieldWriter(StringBuilder b, JsonNumbers numbers, boolean hasMembers) {
        this.b = b;
        this.numbers = numbers;
        open.push(new boolean[] { hasMembers });
    }

    /** The body as one JSON object. */
    public static String object(MessageBody body, JsonNumbers numbers) {
        StringBuilder b = new StringBuilder(256).append('{');
        body.describe(new JsonFieldWriter(b, numbers, false));
        return b.append('}').toString();
    }

    private void key(@Nullable String name) {
        boolean[] o = open.peek();
        if (o[0]) {
            b.append(',');
        }
        o[0] = true;
        if (name != null) {
            JsonText.string(b, name);
            b.append(':');
        }
    }

    @Override
    public void integer(@Nullable String name, long value) {
        key(name);
        b.append(value);
    }

    @Override
    public void float32(@Nullable String name, float value) {
        key(name);
        numbers.appendFloat(b, value);
    }

    @Override
    public void float64(@Nullable String name, double value) {
        key(name);
        numbers.appendDouble(b, value);
    }

    @Override
    public void text(@Nullable String name, String value) {
        key(name);
        JsonText.string(b, value);
    }

    @Override
    public void opaque(@Nullable String name, byte[] value) {
        key(name);
        JsonText.string(b, Base64.getEncoder().encodeToString(value));
    }

    @Override
    public void beginStruct(@Nullable String name) {
        key(name);
        b.append('{');
        open.push(new boolean[1]);
    }

    @Override
    public void endStruct() {
        open.pop();
        b.append('}');
    }

    @Override
    public void beginList(@Nullable String name) {
        key(name);
        b.append('[');
        open.push(new boolean[1]);
    }

    @Override
    public void endList() {
        open.pop();
        b.append(']');
    }
}
