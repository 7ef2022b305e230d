package org.stagecraft.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Base64;

import org.stagecraft.player.codec.FieldVisitor;

import com.google.gson.stream.JsonWriter;

/**
 * Writes decoded fields as JSON. Numbers are exact: a double prints as the shortest text that
 * parses back to the same double; a float prints as the double it widens to, so it parses back to
 * the same value as float or double. NaN and infinities, which JSON lacks, print as strings.
 */
public final class JsonFields implements FieldVisitor {
    private final JsonWriter out;

    public JsonFields(JsonWriter out) {
        this.out = out;
    }

    public static void number(JsonWriter out, double value) throws IOException {
        if (Double.isNaN(value) || Double.isInfinite(value)) {
            out.value(Double.toString(value));
        } else {
            out.value(value);
        }
    }

    private JsonWriter name(String name) throws IOException {
        return name == null ? out : out.name(name);
    }

    @Override
    public void integer(String name, long value) {
        try {
            name(name).value(value);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void float32(String name, float value) {
        float64(name, value);
    }

    @Override
    public void float64(String name, double value) {
        try {
            name(name);
            number(out, value);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void text(String name, String value) {
        try {
            name(name).value(value);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void opaque(String name, byte[] value) {
        text(name, Base64.getEncoder().encodeToString(value));
    }

    @Override
    public void beginStruct(String name) {
        try {
            name(name).beginObject();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void endStruct() {
        try {
            out.endObject();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void beginList(String name) {
        try {
            name(name).beginArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void endList() {
        try {
            out.endArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
