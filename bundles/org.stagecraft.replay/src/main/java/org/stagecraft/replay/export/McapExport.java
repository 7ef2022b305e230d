package org.stagecraft.replay.export;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A log as an MCAP file Foxglove shows: one JSON channel per stream, topic
 * {@code /<port>/<iface>:<index>/<TYPE>/<SUBTYPE>} (e.g. {@code /6665/laser:0/DATA/SCAN}), message
 * encoding {@code json}, a JSON Schema per kind of message generated from its fields, log time the
 * recorded time. The file is also a complete spy log: the wire channels (every banner, message and
 * piece of unframed bytes, exact) and the connection events are written as the spy writes them, so
 * nothing is lost and Stagecraft opens the export like any spy log. With a filter, the wire channels
 * hold only the messages taken (their streams then have gaps); banners, unframed bytes, events and
 * diagnostics in the time range are always kept.
 */
public final class McapExport {
    /** What was written. */
    public record Summary(long wireEntries, long jsonMessages, int jsonChannels) {
    }

    private record Kind(int port, int interf, int index, int type, int subtype) {
    }

    private McapExport() {
    }

    public static Summary write(SessionLog log, ExportFilter filter, CodecRegistry registry, Path out) throws IOException {
        Map<String, String> meta = new TreeMap<>();
        meta.put("exported-from", log.path().toString());
        meta.put("format", log.format().name());
        meta.put("filter", filter.isAll() ? "none" : filter.toString());
        Map<Kind, Integer> channels = new HashMap<>();
        long wire = 0;
        long json = 0;
        long start = log.startNanos();
        long from = filter.fromSeconds() == null ? Long.MIN_VALUE : start + Math.round(filter.fromSeconds() * 1e9);
        try (SpyLogWriter w = SpyLogWriter.create(out, meta); LogCursor c = log.cursor(from)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                if (!filter.inTime(m.timeNanos(), start)) {
                    if (filter.untilSeconds() != null && (m.timeNanos() - start) / 1e9 > filter.untilSeconds()) {
                        break;
                    }
                    continue;
                }
                ConnectionInfo ci = m.connection();
                switch (m.kind()) {
                    case OPENED -> w.connectionOpened(m.timeNanos(), ci.id(), ci.client(), ci.listen(), ci.upstream());
                    case CLOSED -> w.connectionClosed(m.timeNanos(), ci.id(), m.text());
                    case DIAGNOSTIC -> w.diagnostic(m.timeNanos(), ci.id(), m.dir(), m.streamOffset(), m.text());
                    case BANNER, UNFRAMED -> {
                        w.wire(m.timeNanos(), ci.id(), ci.port(), m.dir(), m.streamOffset(),
                                m.kind() == LogMessage.Kind.BANNER ? LogEntry.Kind.BANNER : LogEntry.Kind.UNFRAMED,
                                m.bytes(), m.text());
                        wire++;
                    }
                    case FRAME -> {
                        if (!filter.takes(m, registry)) {
                            continue;
                        }
                        w.wire(m.timeNanos(), ci.id(), ci.port(), m.dir(), m.streamOffset(), LogEntry.Kind.FRAME,
                                m.bytes(), "");
                        wire++;
                        MessageHeader h = m.decoded().header();
                        Kind k = new Kind(ci.port(), h.interf(), h.index(), h.type(), h.subtype());
                        Integer channel = channels.get(k);
                        if (channel == null) {
                            channel = addChannel(w, registry, k, m);
                            channels.put(k, channel);
                        }
                        w.message(channel, m.timeNanos(),
                                JsonBody.of(h, m.decoded().body()).getBytes(StandardCharsets.UTF_8));
                        json++;
                    }
                }
            }
        }
        return new Summary(wire, json, channels.size());
    }

    /** The topic of a kind of message on a Player port. */
    static String topic(CodecRegistry registry, int port, MessageHeader h) {
        return "/" + port + "/" + Names.iface(registry, h.interf()) + ":" + h.index() + "/" + Names.type(h.type()) + "/"
                + Names.subtype(registry, h);
    }

    private static int addChannel(SpyLogWriter w, CodecRegistry registry, Kind k, LogMessage first) throws IOException {
        MessageHeader h = first.decoded().header();
        String title = "player " + Names.iface(registry, h.interf()) + " " + Names.type(h.type()) + " "
                + Names.subtype(registry, h);
        String schema = JsonSchemaOf.of(title, first.decoded().body());
        return w.addChannel(topic(registry, k.port(), h), "json", title.replace(' ', '.'), "jsonschema",
                schema.getBytes(StandardCharsets.UTF_8),
                Map.of("port", Integer.toString(k.port()), "interface", Names.iface(registry, k.interf()),
                        "index", Integer.toString(k.index())));
    }
}
