package org.stagecraft.foxglove.live;

import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.foxglove.FoxgloveChannel;
import org.stagecraft.foxglove.FoxgloveSink;
import org.stagecraft.foxglove.player.PlayerJson;
import org.stagecraft.foxglove.player.PlayerJsonSchema;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.spy.proxy.SpyMessage;
import org.stagecraft.streams.StreamMessage;

/**
 * Player's own messages, decoded, live: one JSON channel per stream (one connection's messages of one
 * kind), with the export's topics ({@code /<port>/<conn>/<iface>:<index>/<TYPE>/<SUBTYPE>}, e.g.
 * {@code /6665/1/laser:0/DATA/SCAN}), schema names and JSON, so a viewer plots by Player's field names
 * as on an exported file. An export knows every message before it writes a schema; live, the schema is
 * that of the messages seen so far: when a message brings a new layout (a NACK with a body after one
 * without, say), the channel is advertised again with the merged schema, so every message sent is valid
 * against the schema of the channel it is sent on. Used from one thread (the relay's consumer).
 */
public final class PlayerChannels {
    private record Stream(int port, int conn, int interf, int index, int type, int subtype) {
    }

    private static final class State {
        final String topic;
        final String title;
        final PlayerJsonSchema.Node schema;
        @Nullable FoxgloveChannel channel;

        State(String topic, String title, PlayerJsonSchema.Node schema) {
            this.topic = topic;
            this.title = title;
            this.schema = schema;
        }
    }

    private final FoxgloveSink sink;
    private final CodecRegistry registry;
    private final Map<Stream, State> streams = new HashMap<>();

    public PlayerChannels(FoxgloveSink sink, CodecRegistry registry) {
        this.sink = sink;
        this.registry = registry;
    }

    /** Takes one bus message; anything but a Player message is ignored. */
    public void accept(StreamMessage m) {
        if (!(m.payload() instanceof SpyMessage s)) {
            return;
        }
        MessageHeader h = s.message().header();
        Stream k = new Stream(s.connection().port(), s.connection().id(), h.interf(), h.index(), h.type(), h.subtype());
        PlayerJsonSchema.Node layout = PlayerJsonSchema.of(s.message().body());
        State st = streams.get(k);
        if (st == null) {
            String iface = iface(h.interf());
            String type = type(h.type());
            String subtype = registry.subtypeName(h.interf(), h.type(), h.subtype());
            st = new State("/" + k.port() + "/" + k.conn() + "/" + iface + ":" + h.index() + "/" + type + "/" + subtype,
                    "player " + iface + " " + type + " " + subtype, layout);
            streams.put(k, st);
        } else {
            st.schema.merge(layout);
        }
        FoxgloveChannel c = FoxgloveChannel.json(st.topic, st.title.replace(' ', '.'), PlayerJsonSchema.text(st.title, st.schema));
        if (!Objects.equals(c, st.channel)) {
            if (st.channel != null) {
                sink.unadvertise(st.channel); // its schema grew: viewers get the channel anew
            }
            sink.advertise(c);
            st.channel = c;
        }
        sink.publish(c, m.timeNanos(), m.timeNanos(), PlayerJson.of(h, s.message().body()).getBytes(StandardCharsets.UTF_8));
    }

    // Player's names for what a header says, as the export names its channels (McapExport's Names)
    private String iface(int interf) {
        String n = registry.interfaceName(interf);
        return n != null ? n : Integer.toString(interf);
    }

    private static String type(int type) {
        MessageType t = MessageType.of(type);
        return t != null ? t.name() : Integer.toString(type);
    }
}
