package org.stagecraft.foxglove.player;

import java.util.ArrayDeque;
import java.util.Base64;
import java.util.Deque;

import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.MessageBody;
import org.stagecraft.player.wire.MessageHeader;

/**
 * A decoded message as one JSON object: {@code header} (Player's timestamp, seq, host and robot),
 * then the body's fields by Player's names, numbers exact (a float32 as the shortest text of that
 * float), opaque bytes in base64. The MCAP export's Player channels, and the live view's.
 */
public final class PlayerJson implements FieldVisitor {
    private final StringBuilder b = new StringBuilder(1024);
    /** Per open object or array: whether something was written in it yet. */
    private final Deque<boolean[]> open = new ArrayDeque<>();

    private PlayerJson() {
    }

    /** The message as JSON text. */
    public static String of(MessageHeader h, MessageBody body) {
        PlayerJson j = new PlayerJson();
        j.b.append("{\"header\":{\"timestamp\":");
        JsonText.number(j.b, h.timestamp(), false);
        j.b.append(",\"seq\":").append(h.seqUnsigned()).append(",\"host\":").append(h.hostUnsigned())
                .append(",\"robot\":").append(h.robotUnsigned()).append('}');
        j.open.push(new boolean[] { true });
        body.describe(j);
        j.b.append('}');
        return j.b.toString();
    }

    private void key(String name) {
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
    public void integer(String name, long value) {
        key(name);
        b.append(value);
    }

    @Override
    public void float32(String name, float value) {
        key(name);
        JsonText.number(b, value, true);
    }

    @Override
    public void float64(String name, double value) {
        key(name);
        JsonText.number(b, value, false);
    }

    @Override
    public void text(String name, String value) {
        key(name);
        JsonText.string(b, value);
    }

    @Override
    public void opaque(String name, byte[] value) {
        key(name);
        JsonText.string(b, Base64.getEncoder().encodeToString(value));
    }

    @Override
    public void beginStruct(String name) {
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
    public void beginList(String name) {
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
