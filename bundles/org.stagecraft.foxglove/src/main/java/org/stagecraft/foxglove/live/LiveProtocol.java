package org.stagecraft.foxglove.live;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.foxglove.FoxgloveChannel;

/**
 * The messages of the Foxglove WebSocket protocol v1 (subprotocol {@code foxglove.websocket.v1}) that this
 * server speaks: JSON text messages with an {@code op} field, and binary messages that start with a
 * one-byte opcode followed by little-endian integers. Only encoding and parsing live here; what to send
 * when is {@link FoxgloveServer}'s.
 */
final class LiveProtocol {
    static final String SUBPROTOCOL = "foxglove.websocket.v1";

    /** Binary opcodes sent by the server. */
    static final byte MESSAGE_DATA = 0x01;
    static final byte TIME = 0x02;

    /** Status levels. */
    static final int INFO = 0;
    static final int WARNING = 1;
    static final int ERROR = 2;

    private LiveProtocol() {
    }

    /** The capabilities this server announces: it publishes time, the clock of its messages' log times. */
    static final List<String> CAPABILITIES = List.of("time");

    static String serverInfo(String name, String sessionId, Map<String, String> metadata) {
        JsonObject o = op("serverInfo");
        o.addProperty("name", name);
        JsonArray caps = new JsonArray();
        CAPABILITIES.forEach(caps::add);
        o.add("capabilities", caps);
        JsonObject meta = new JsonObject();
        metadata.forEach(meta::addProperty);
        o.add("metadata", meta);
        o.addProperty("sessionId", sessionId);
        return o.toString();
    }

    /** A channel as advertised: the server's id for it and what it is. */
    record Advertised(int id, FoxgloveChannel channel) {
    }

    static String advertise(Collection<Advertised> channels) {
        JsonObject o = op("advertise");
        JsonArray list = new JsonArray();
        for (Advertised a : channels) {
            JsonObject c = new JsonObject();
            c.addProperty("id", a.id());
            c.addProperty("topic", a.channel().topic());
            c.addProperty("encoding", a.channel().messageEncoding());
            c.addProperty("schemaName", a.channel().schemaName());
            c.addProperty("schema", a.channel().schema());
            c.addProperty("schemaEncoding", a.channel().schemaEncoding());
            list.add(c);
        }
        o.add("channels", list);
        return o.toString();
    }

    static String unadvertise(Collection<Integer> channelIds) {
        JsonObject o = op("unadvertise");
        JsonArray ids = new JsonArray();
        channelIds.forEach(ids::add);
        o.add("channelIds", ids);
        return o.toString();
    }

    /** @param id a status with the same id replaces the previous one in the viewer, or null */
    static String status(int level, String message, @Nullable String id) {
        JsonObject o = op("status");
        o.addProperty("level", level);
        o.addProperty("message", message);
        if (id != null) {
            o.addProperty("id", id);
        }
        return o.toString();
    }

    /** Opcode 1: subscription id (uint32), log/receive time (uint64 ns), payload. */
    static ByteBuffer messageData(int subscriptionId, long logTimeNanos, byte[] payload) {
        ByteBuffer b = ByteBuffer.allocate(1 + 4 + 8 + payload.length).order(ByteOrder.LITTLE_ENDIAN);
        b.put(MESSAGE_DATA).putInt(subscriptionId).putLong(logTimeNanos).put(payload);
        return b.flip();
    }

    /** Opcode 2: the server's current time (uint64 ns), on the clock of the messages' log times. */
    static ByteBuffer time(long nanos) {
        ByteBuffer b = ByteBuffer.allocate(1 + 8).order(ByteOrder.LITTLE_ENDIAN);
        b.put(TIME).putLong(nanos);
        return b.flip();
    }

    // ---- what a client sends -------------------------------------------------------------------

    /** One client request, parsed. */
    sealed interface Request {
    }

    record Subscription(int id, int channelId) {
    }

    record Subscribe(List<Subscription> subscriptions) implements Request {
    }

    record Unsubscribe(List<Integer> subscriptionIds) implements Request {
    }

    /** A well-formed request for a feature this server does not announce (client publishing, parameters...). */
    record Unsupported(String op) implements Request {
    }

    /**
     * Parses a client's text message.
     *
     * @throws IllegalArgumentException naming what is wrong, for a status message back to the client
     */
    static Request parse(String text) {
        JsonObject o;
        try {
            JsonElement e = JsonParser.parseString(text);
            if (!e.isJsonObject()) {
                throw new IllegalArgumentException("not a JSON object");
            }
            o = e.getAsJsonObject();
        } catch (JsonParseException e) {
            throw new IllegalArgumentException("not JSON: " + e.getMessage(), e);
        }
        String op = string(o, "op");
        try {
            return switch (op) {
                case "subscribe" -> {
                    List<Subscription> subs = new ArrayList<>();
                    for (JsonElement s : array(o, "subscriptions")) {
                        JsonObject so = s.getAsJsonObject();
                        subs.add(new Subscription(uint32(so, "id"), uint32(so, "channelId")));
                    }
                    yield new Subscribe(subs);
                }
                case "unsubscribe" -> {
                    List<Integer> ids = new ArrayList<>();
                    for (JsonElement s : array(o, "subscriptionIds")) {
                        ids.add(uint32(s, "subscriptionIds[]"));
                    }
                    yield new Unsubscribe(ids);
                }
                default -> new Unsupported(op);
            };
        } catch (IllegalStateException | UnsupportedOperationException e) { // Gson's "not an object/number"
            throw new IllegalArgumentException("'" + op + "': malformed (" + e.getMessage() + ")", e);
        }
    }

    private static JsonObject op(String op) {
        JsonObject o = new JsonObject();
        o.addProperty("op", op);
        return o;
    }

    private static String string(JsonObject o, String field) {
        JsonElement e = o.get(field);
        if (e == null || !e.isJsonPrimitive() || !e.getAsJsonPrimitive().isString()) {
            throw new IllegalArgumentException("no string field '" + field + "'");
        }
        return e.getAsString();
    }

    private static JsonArray array(JsonObject o, String field) {
        JsonElement e = o.get(field);
        if (e == null || !e.isJsonArray()) {
            throw new IllegalArgumentException("'" + string(o, "op") + "' has no array '" + field + "'");
        }
        return e.getAsJsonArray();
    }

    private static int uint32(JsonObject o, String field) {
        JsonElement e = o.get(field);
        if (e == null) {
            throw new IllegalArgumentException("no field '" + field + "'");
        }
        return uint32(e, field);
    }

    /** A uint32 in an int (ids above 2^31 keep their bits; they go back on the wire as uint32). */
    private static int uint32(JsonElement e, String field) {
        if (!e.isJsonPrimitive() || !e.getAsJsonPrimitive().isNumber()) {
            throw new IllegalArgumentException("'" + field + "' is not a number");
        }
        double d = e.getAsDouble();
        if (d < 0 || d > 0xFFFF_FFFFL || d != Math.rint(d)) {
            throw new IllegalArgumentException("'" + field + "' " + e + " is not a uint32");
        }
        return (int) (long) d;
    }
}
