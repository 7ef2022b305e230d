package org.stagecraft.foxglove;

import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

import com.google.gson.stream.JsonWriter;

/**
 * Writes one Foxglove message as JSON, with the pieces the well-known schemas share (time, pose,
 * colour). Numbers that JSON cannot hold (NaN, infinities, which Stage leaves in some geometry) are
 * written as 0: the schemas allow numbers only.
 */
final class JsonOut {
    private final StringWriter text = new StringWriter(512);
    private final JsonWriter w = new JsonWriter(text);

    JsonOut() {
        w.setHtmlSafe(false);
    }

    JsonOut begin() {
        return io(() -> w.beginObject());
    }

    JsonOut end() {
        return io(() -> w.endObject());
    }

    JsonOut beginObject(String name) {
        return io(() -> w.name(name).beginObject());
    }

    JsonOut beginArray(String name) {
        return io(() -> w.name(name).beginArray());
    }

    JsonOut endArray() {
        return io(() -> w.endArray());
    }

    JsonOut string(String name, String value) {
        return io(() -> w.name(name).value(value));
    }

    JsonOut integer(String name, long value) {
        return io(() -> w.name(name).value(value));
    }

    JsonOut bool(String name, boolean value) {
        return io(() -> w.name(name).value(value));
    }

    JsonOut number(String name, double value) {
        return io(() -> w.name(name).value(finite(value)));
    }

    /** A float32 as the shortest decimal that reads back as the same float (0.1f, not 0.10000000149). */
    JsonOut float32(String name, float value) {
        return number(name, Float.isFinite(value) ? Double.parseDouble(Float.toString(value)) : 0);
    }

    /** An element of an open array. */
    JsonOut element(double value) {
        return io(() -> w.value(finite(value)));
    }

    JsonOut element(float value) {
        return element(Float.isFinite(value) ? Double.parseDouble(Float.toString(value)) : 0);
    }

    /** Foxglove's time {sec, nsec} of epoch nanoseconds. */
    JsonOut time(String name, long epochNanos) {
        return beginObject(name).integer("sec", Math.floorDiv(epochNanos, 1_000_000_000L))
                .integer("nsec", Math.floorMod(epochNanos, 1_000_000_000L)).end();
    }

    JsonOut duration(String name, long nanos) {
        return time(name, nanos);
    }

    JsonOut vector(String name, double x, double y, double z) {
        return beginObject(name).number("x", x).number("y", y).number("z", z).end();
    }

    /** A rotation by {@code yaw} about z as a quaternion. */
    JsonOut yaw(String name, double yaw) {
        double a = finite(yaw) / 2;
        return beginObject(name).number("x", 0).number("y", 0).number("z", Math.sin(a)).number("w", Math.cos(a)).end();
    }

    /** A planar pose (x, y, yaw) at height z. */
    JsonOut pose(String name, double x, double y, double z, double yaw) {
        beginObject(name);
        vector("position", x, y, z);
        return yaw("orientation", yaw).end();
    }

    /** A pose as an element of an open array. */
    JsonOut poseElement(double x, double y, double z, double yaw) {
        io(() -> w.beginObject());
        vector("position", x, y, z);
        return yaw("orientation", yaw).end();
    }

    JsonOut beginElement() {
        return io(() -> w.beginObject());
    }

    JsonOut color(String name, double r, double g, double b, double a) {
        return beginObject(name).number("r", r).number("g", g).number("b", b).number("a", a).end();
    }

    JsonOut point(double x, double y, double z) {
        return beginElement().number("x", x).number("y", y).number("z", z).end();
    }

    byte[] bytes() {
        io(() -> w.flush());
        return text.toString().getBytes(StandardCharsets.UTF_8);
    }

    static double finite(double v) {
        return Double.isFinite(v) ? v : 0;
    }

    private interface Write {
        void run() throws IOException;
    }

    private JsonOut io(Write op) {
        try {
            op.run();
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringWriter does not fail
        }
        return this;
    }
}
