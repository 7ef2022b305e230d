package org.stagecraft.spy.log;

import java.nio.charset.StandardCharsets;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.wire.Direction;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The spy log's layout inside MCAP: its schemas, channels and the encoding of its message data. See
 * docs/spy-log.md.
 */
final class Layout {
    private Layout() {
    }

    /**
     * The header's profile: none. MCAP's tools warn about any profile but their well-known ones
     * ("ros1", "ros2"); a spy log is told by its session metadata ({@link #METADATA_SESSION}).
     * Logs written before version 2 say "x-stagecraft-spy".
     */
    static final String PROFILE = "";
    static final String LIBRARY = "stagecraft spy log 2";

    static final String SCHEMA_EVENT_NAME = "stagecraft.SpyEvent";
    static final String EVENT_ENCODING = "json";
    static final String TOPIC_EVENTS = "/events";

    /** Wire and hold channels: protobuf messages (see {@link WireProto}). */
    static final String PROTOBUF = "protobuf";
    /** The wire channels' encoding in logs written before version 2 (no schema, see docs/spy-log.md). */
    static final String OLD_WIRE_ENCODING = "x-player-xdr";

    static final String METADATA_SESSION = "stagecraft.session";

    /**
     * Stagecraft's own channel: what a robot hold injected or held back (docs/debugging-robots.md).
     * One channel for the whole log; each message names its connection.
     */
    static final String TOPIC_HOLD = "/stagecraft/hold";
    /** The hold channel's encoding in logs written before version 2. */
    static final String OLD_HOLD_ENCODING = "x-stagecraft-hold";

    static final String EVENT_SCHEMA_JSON = """
            {"$schema":"https://json-schema.org/draft/2020-12/schema","title":"Stagecraft spy event",\
            "type":"object","required":["event","conn"],\
            "properties":{"event":{"type":"string","enum":["opened","closed","diagnostic"]},\
            "conn":{"type":"integer"},"client":{"type":"string"},"listen":{"type":"string"},\
            "upstream":{"type":"string"},"reason":{"type":"string"},\
            "dir":{"type":"string","enum":["c2s","s2c"]},"offset":{"type":"integer"},"text":{"type":"string"}}}""";

    static String wireTopic(int conn, int port, Direction dir) {
        return "/wire/" + conn + "/" + port + "/" + dir.label();
    }

    /**
     * A wire channel's metadata: its stream, and the connection's addresses when the connection was
     * opened in this log, so a reader knows every connection from the summary without reading chunks.
     */
    static Map<String, String> wireChannelMetadata(int conn, int port, Direction dir, Map<String, String> addresses) {
        Map<String, String> m = new java.util.TreeMap<>(addresses);
        m.put("conn", Integer.toString(conn));
        m.put("port", Integer.toString(port));
        m.put("dir", dir.label());
        return m;
    }

    static final String META_CLIENT = "client";
    static final String META_LISTEN = "listen";
    static final String META_UPSTREAM = "upstream";

    static Map<String, String> addressMetadata(String client, String listen, String upstream) {
        return Map.of(META_CLIENT, nz(client), META_LISTEN, nz(listen), META_UPSTREAM, nz(upstream));
    }

    static int kindCode(LogEntry.Kind k) {
        return k.ordinal() + 1;
    }

    static LogEntry.Kind kind(int code) throws SpyLogFormatException {
        LogEntry.Kind[] all = LogEntry.Kind.values();
        if (code < 1 || code > all.length) {
            throw new SpyLogFormatException("unknown wire record kind " + code);
        }
        return all[code - 1];
    }

    static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    // --- events (JSON) ---------------------------------------------------------------------------

    static byte[] opened(int conn, String client, String listen, String upstream) {
        JsonObject o = new JsonObject();
        o.addProperty("event", "opened");
        o.addProperty("conn", conn);
        o.addProperty("client", nz(client));
        o.addProperty("listen", nz(listen));
        o.addProperty("upstream", nz(upstream));
        return utf8(o.toString());
    }

    static byte[] closed(int conn, String reason) {
        JsonObject o = new JsonObject();
        o.addProperty("event", "closed");
        o.addProperty("conn", conn);
        o.addProperty("reason", nz(reason));
        return utf8(o.toString());
    }

    static byte[] diagnostic(int conn, @Nullable Direction dir, long offset, String text) {
        JsonObject o = new JsonObject();
        o.addProperty("event", "diagnostic");
        o.addProperty("conn", conn);
        if (dir != null) {
            o.addProperty("dir", dir.label());
        }
        o.addProperty("offset", offset);
        o.addProperty("text", nz(text));
        return utf8(o.toString());
    }

    static LogEntry event(long time, byte[] data, int off, int len) throws SpyLogFormatException {
        try {
            JsonObject o = JsonParser.parseString(new String(data, off, len, StandardCharsets.UTF_8)).getAsJsonObject();
            String ev = o.get("event").getAsString();
            int conn = o.get("conn").getAsInt();
            return switch (ev) {
                case "opened" -> new LogEntry.Opened(time, conn, str(o, "client"), str(o, "listen"), str(o, "upstream"));
                case "closed" -> new LogEntry.Closed(time, conn, str(o, "reason"));
                case "diagnostic" -> new LogEntry.Diagnostic(time, conn,
                        o.has("dir") ? Direction.fromLabel(o.get("dir").getAsString()) : null,
                        o.has("offset") ? o.get("offset").getAsLong() : -1, str(o, "text"));
                default -> throw new SpyLogFormatException("unknown event \"" + ev + "\"");
            };
        } catch (RuntimeException e) {
            throw new SpyLogFormatException("an event is not the JSON this log writes (" + e.getMessage() + ")", e);
        }
    }

    private static String str(JsonObject o, String key) {
        return o.has(key) && !o.get(key).isJsonNull() ? o.get(key).getAsString() : "";
    }

    private static String nz(String s) {
        return s == null ? "" : s;
    }
}
