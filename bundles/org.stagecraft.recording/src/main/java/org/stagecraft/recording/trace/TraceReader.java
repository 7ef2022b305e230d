package org.stagecraft.recording.trace;

import java.io.BufferedReader;
import java.io.Closeable;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.Map;

import org.stagecraft.player.session.StreamId;
import org.stagecraft.player.wire.Direction;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;

/**
 * Reads a player-trace JSON-lines file record by record, in file order (= observation order).
 * Streams the file; memory does not grow with its size.
 */
public final class TraceReader implements Closeable {
    public static final String FORMAT = "player-trace";

    private final String name;
    private final BufferedReader in;
    private long line;
    private boolean sawHeader;

    public TraceReader(Path file) throws IOException {
        this(file.toString(), Files.newBufferedReader(file, StandardCharsets.UTF_8));
    }

    public TraceReader(String name, BufferedReader in) {
        this.name = name;
        this.in = in;
    }

    /** @return the next record, or null at the end of the file */
    public TraceRecord next() throws IOException {
        String text;
        do {
            text = in.readLine();
            if (text == null) {
                if (!sawHeader) {
                    throw new TraceFormatException(name + ": empty file, expected a \"" + FORMAT + "\" header line");
                }
                return null;
            }
            line++;
        } while (text.isBlank());
        JsonObject o;
        try {
            JsonElement e = JsonParser.parseString(text);
            if (!e.isJsonObject()) {
                throw fail("expected a JSON object");
            }
            o = e.getAsJsonObject();
        } catch (JsonParseException e) {
            throw new TraceFormatException(where() + "not valid JSON (" + e.getMessage() + ")", e);
        }
        if (!sawHeader) {
            sawHeader = true;
            return header(o);
        }
        try {
            if (o.has("event")) {
                return new TraceRecord.Lifecycle(line, number(o, "t"), (int) integer(o, "conn"), (int) integer(o, "port"),
                        string(o, "event"));
            }
            Direction dir;
            try {
                dir = Direction.fromLabel(string(o, "dir"));
            } catch (IllegalArgumentException e) {
                throw fail(e.getMessage());
            }
            byte[] data;
            try {
                data = Base64.getDecoder().decode(string(o, "data"));
            } catch (IllegalArgumentException e) {
                throw fail("\"data\" is not base64 (" + e.getMessage() + ")");
            }
            return new TraceRecord.Chunk(line, number(o, "t"),
                    new StreamId((int) integer(o, "conn"), (int) integer(o, "port"), dir), data);
        } catch (ClassCastException | IllegalStateException | UnsupportedOperationException | NumberFormatException e) {
            throw fail("a field has the wrong type (" + e.getMessage() + ")");
        }
    }

    private TraceRecord.Header header(JsonObject o) throws TraceFormatException {
        JsonElement format = o.get("format");
        if (format == null || !format.isJsonPrimitive() || !FORMAT.equals(format.getAsString())) {
            throw fail("expected a header with \"format\":\"" + FORMAT + "\"");
        }
        JsonElement version = o.get("version");
        if (version == null || !version.isJsonPrimitive() || version.getAsInt() != 1) {
            throw fail("unsupported player-trace version " + version + " (this reader knows version 1)");
        }
        Map<String, String> fields = new LinkedHashMap<>();
        for (Map.Entry<String, JsonElement> e : o.entrySet()) {
            fields.put(e.getKey(), e.getValue().isJsonPrimitive() ? e.getValue().getAsString() : e.getValue().toString());
        }
        return new TraceRecord.Header(line, fields);
    }

    private String where() {
        return name + ":" + line + ": ";
    }

    private TraceFormatException fail(String why) {
        return new TraceFormatException(where() + why);
    }

    private JsonElement field(JsonObject o, String key) throws TraceFormatException {
        JsonElement e = o.get(key);
        if (e == null || e.isJsonNull()) {
            throw fail("missing \"" + key + "\"");
        }
        return e;
    }

    private String string(JsonObject o, String key) throws TraceFormatException {
        return field(o, key).getAsString();
    }

    private double number(JsonObject o, String key) throws TraceFormatException {
        return field(o, key).getAsDouble();
    }

    private long integer(JsonObject o, String key) throws TraceFormatException {
        return field(o, key).getAsLong();
    }

    public long line() {
        return line;
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
