package org.stagecraft.recording.trace;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
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
    private final TraceLines in;
    private long line;
    private boolean sawHeader;

    public TraceReader(Path file) throws IOException {
        this(file.toString(), Files.newInputStream(file));
    }

    /**
     * Reads UTF-8 JSON lines from {@code in}, named {@code name} in error messages. Memory per line is
     * bounded: a line longer than 16 MiB is refused (see {@link TraceLines#MAX_LINE_BYTES}).
     */
    public TraceReader(String name, InputStream in) {
        this.name = name;
        this.in = new TraceLines(name, in);
    }

    /** @return the next record, or null at the end of the file */
    public @Nullable TraceRecord next() throws IOException {
        String text;
        do {
            text = in.next();
            if (text == null) {
                if (!sawHeader) {
                    throw new TraceFormatException(name, 0, "empty file, expected a \"" + FORMAT + "\" header line");
                }
                return null;
            }
            line = in.lineNumber();
        } while (text.isBlank());
        JsonObject o;
        try {
            JsonElement e = JsonParser.parseString(text);
            if (!e.isJsonObject()) {
                throw fail("expected a JSON object");
            }
            o = e.getAsJsonObject();
        } catch (JsonParseException e) {
            if (e.getCause() instanceof OutOfMemoryError) { // Gson wraps it; it is not the line's fault
                throw fail("the line (" + text.length() + " characters) does not fit in the memory left (maximum heap "
                        + (Runtime.getRuntime().maxMemory() >> 20) + " MiB)");
            }
            throw new TraceFormatException(name, line, "not valid JSON (" + parserMessage(e) + ")", e);
        } catch (StackOverflowError e) { // nesting deeper than the parser's stack: not a trace line anyway
            throw fail("not valid JSON (nested too deeply)");
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
        if (version == null) {
            throw fail("the header has no \"version\" (this reader knows player-trace version 1)");
        }
        if (!isVersionOne(version)) {
            throw fail("unsupported player-trace version " + abbreviate(version.toString())
                    + " (this reader knows version 1)");
        }
        Map<String, String> fields = new LinkedHashMap<>();
        for (Map.Entry<String, JsonElement> e : o.entrySet()) {
            fields.put(e.getKey(), e.getValue().isJsonPrimitive() ? e.getValue().getAsString() : e.getValue().toString());
        }
        return new TraceRecord.Header(line, fields);
    }

    private static boolean isVersionOne(JsonElement version) {
        if (!version.isJsonPrimitive()) {
            return false;
        }
        try {
            return new java.math.BigDecimal(version.getAsString()).compareTo(java.math.BigDecimal.ONE) == 0;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    /** What the parser said, without the exception class name or the link it appends on a line of its own. */
    private static String parserMessage(Throwable e) {
        Throwable t = e;
        while (t.getCause() != null && t.getCause() != t) {
            t = t.getCause();
        }
        String m = t.getMessage() != null ? t.getMessage() : e.getMessage();
        if (m == null) {
            return "unreadable";
        }
        int nl = m.indexOf('\n');
        return nl < 0 ? m : m.substring(0, nl);
    }

    /** A value quoted in a message: short enough to read. */
    private static String abbreviate(String text) {
        return text.length() <= 40 ? text : text.substring(0, 40) + "...";
    }

    private TraceFormatException fail(String why) {
        return new TraceFormatException(name, line, why);
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
