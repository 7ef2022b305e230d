package org.stagecraft.cli;

import java.io.IOException;
import java.io.StringWriter;
import java.util.Base64;

import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.codec.RawBody;
import org.stagecraft.player.json.JsonFieldWriter;
import org.stagecraft.player.json.JsonNumbers;
import org.stagecraft.player.session.SessionEvent;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.WireEvent;

import com.google.gson.stream.JsonWriter;

/**
 * One JSON object per framed event: {@code t, conn, port, dir}, then the banner's {@code ident},
 * or the header fields and the decoded {@code body}, or an {@code error} with its stream
 * {@code offset}. Numbers and bodies are written by {@link JsonFieldWriter} with
 * {@link JsonNumbers#LOSSLESS} (NaN and infinities as strings, a float32 as the double it widens to).
 */
public final class EventJson {
    private final PlayerDecoder decoder;

    public EventJson(PlayerDecoder decoder) {
        this.decoder = decoder;
    }

    public String toJson(SessionEvent e) {
        StringWriter text = new StringWriter(256);
        try (JsonWriter out = new JsonWriter(text)) {
            out.beginObject();
            out.name("t").jsonValue(JsonNumbers.LOSSLESS.text(e.t()));
            out.name("conn").value(e.stream().conn());
            out.name("port").value(e.stream().port());
            out.name("dir").value(e.stream().dir().label());
            switch (e.event()) {
                case WireEvent.Banner b -> out.name("ident").value(b.ident());
                case WireEvent.Frame f -> message(out, f);
                case WireEvent.Unframed u -> {
                    out.name("error").value(u.reason());
                    out.name("offset").value(u.offset());
                    out.name("length").value(u.length());
                    out.name("bytes").value(Base64.getEncoder().encodeToString(u.bytes()));
                }
            }
            out.endObject();
        } catch (IOException ex) {
            throw new IllegalStateException("writing JSON to a string failed", ex);
        }
        return text.toString();
    }

    private void message(JsonWriter out, WireEvent.Frame f) throws IOException {
        MessageHeader h = f.header();
        DecodedMessage m = decoder.decode(f);
        String iface = decoder.registry().interfaceName(h.interf());
        out.name("host").value(h.hostUnsigned());
        out.name("robot").value(h.robotUnsigned());
        out.name("interf").value(h.interf());
        out.name("iface").value(iface != null ? iface : "unknown");
        out.name("index").value(h.index());
        out.name("type").value(h.type());
        out.name("subtype").value(h.subtype());
        out.name("timestamp").jsonValue(JsonNumbers.LOSSLESS.text(h.timestamp()));
        out.name("seq").value(h.seqUnsigned());
        out.name("size").value(h.sizeUnsigned());
        out.name("body");
        if (m.body() instanceof RawBody raw) {
            out.value(Base64.getEncoder().encodeToString(raw.bytes()));
        } else {
            out.jsonValue(JsonFieldWriter.object(m.body(), JsonNumbers.LOSSLESS));
        }
        if (m.hasProblem()) {
            out.name("error").value(m.problem().reason());
            int inPayload = Math.max(0, m.problem().payloadOffset());
            out.name("offset").value(f.offset() + MessageHeader.SIZE + inPayload);
        }
    }
}
