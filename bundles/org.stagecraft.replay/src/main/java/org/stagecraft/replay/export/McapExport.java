package org.stagecraft.replay.export;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

import org.stagecraft.foxglove.FoxgloveScene;
import org.stagecraft.foxglove.player.PlayerJson;
import org.stagecraft.foxglove.player.PlayerJsonSchema;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.spy.log.LogEntry;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.ConnectionInfo;

/**
 * A log as an MCAP file Foxglove shows. Each robot as Foxglove understands it: the channels of
 * Foxglove's well-known schemas that {@link FoxgloveScene} makes of the log's messages (scans,
 * frames, poses, cones, maps, diagnostics and session events; see there), written as they come.
 * Beside them, Player's own messages decoded: one JSON channel per stream, as on the stream bus (one
 * connection's messages of one kind), topic {@code /<port>/<conn>/<iface>:<index>/<TYPE>/<SUBTYPE>}
 * (e.g. {@code /6665/1/laser:0/DATA/SCAN}): two clients of one device are two streams, and putting
 * them on one channel would show every message twice. Message encoding {@code json}, log time the
 * recorded time. Each channel's JSON Schema is the union of the layouts of all its messages (a NACK
 * with and one without a body, say), so every message validates; that needs a first pass over the
 * taken messages before anything is written. The file is also a complete spy log: the wire channels
 * (every banner, message and piece of unframed bytes, exact) and the connection events are written
 * as the spy writes them, so nothing is lost and Stagecraft opens the export like any spy log. With a
 * filter, the wire channels hold only the messages taken (their streams then have gaps); banners,
 * unframed bytes, events and diagnostics in the time range are always kept.
 */
public final class McapExport {
    /**
     * What was written.
     *
     * @param jsonMessages  Player's decoded messages (one JSON channel per stream)
     * @param jsonChannels  their channels
     * @param foxgloveChannels channels of Foxglove's well-known schemas (robots, scans, frames, logs)
     * @param robots        the robots of the Foxglove channels ({@code robot6665}, ...)
     */
    public record Summary(long wireEntries, long jsonMessages, int jsonChannels, int foxgloveChannels,
            List<String> robots) {
    }

    /** One stream: a connection's messages of one kind. */
    private record Stream(int conn, int port, int interf, int index, int type, int subtype) {
        static Stream of(LogMessage m) {
            MessageHeader h = m.decoded().header();
            return new Stream(m.connection().id(), m.connection().port(), h.interf(), h.index(), h.type(), h.subtype());
        }
    }

    private McapExport() {
    }

    public static Summary write(SessionLog log, ExportFilter filter, CodecRegistry registry, Path out) throws IOException {
        Map<Stream, PlayerJsonSchema.Node> schemas = new HashMap<>();
        forEachTaken(log, filter, registry, m -> {
            if (m.kind() == LogMessage.Kind.FRAME) {
                PlayerJsonSchema.Node n = PlayerJsonSchema.of(m.decoded().body());
                schemas.merge(Stream.of(m), n, PlayerJsonSchema.Node::merge);
            }
        });
        Map<String, String> meta = new TreeMap<>();
        meta.put("exported-from", log.path().toString());
        meta.put("format", log.format().name());
        meta.put("filter", filter.isAll() ? "none" : filter.toString());
        Map<Stream, Integer> channels = new HashMap<>();
        long[] counts = new long[2]; // wire entries, JSON messages
        SpyLogFoxgloveSink foxglove;
        FoxgloveScene scene;
        try (SpyLogWriter w = SpyLogWriter.create(out, meta)) {
            foxglove = new SpyLogFoxgloveSink(w);
            scene = new FoxgloveScene(foxglove);
            forEachTaken(log, filter, registry, m -> {
                ConnectionInfo ci = m.connection();
                switch (m.kind()) {
                    case OPENED -> {
                        w.connectionOpened(m.timeNanos(), ci.id(), ci.client(), ci.listen(), ci.upstream());
                        scene.event(m.timeNanos(), "connection " + ci.id(), "connection " + ci.id() + " opened: "
                                + ci.client() + " -> " + ci.listen() + " (Player at " + ci.upstream() + ")");
                    }
                    case CLOSED -> {
                        w.connectionClosed(m.timeNanos(), ci.id(), m.text());
                        scene.event(m.timeNanos(), "connection " + ci.id(), "connection " + ci.id() + " ("
                                + ci.client() + " -> " + ci.listen() + ") closed: " + m.text());
                    }
                    case DIAGNOSTIC -> {
                        w.diagnostic(m.timeNanos(), ci.id(), m.dir(), m.streamOffset(), m.text());
                        m.toStreamMessage().ifPresent(scene::accept);
                    }
                    case BANNER, UNFRAMED -> {
                        w.wire(m.timeNanos(), ci.id(), ci.port(), Objects.requireNonNull(m.dir()), m.streamOffset(),
                                m.kind() == LogMessage.Kind.BANNER ? LogEntry.Kind.BANNER : LogEntry.Kind.UNFRAMED,
                                m.bytes(), m.text());
                        counts[0]++;
                        m.toStreamMessage().ifPresent(scene::accept);
                    }
                    case HOLD -> {
                        // never among a cursor's entries (only the inspector shows them, see HoldRows)
                    }
                    case FRAME -> {
                        w.wire(m.timeNanos(), ci.id(), ci.port(), Objects.requireNonNull(m.dir()), m.streamOffset(), LogEntry.Kind.FRAME,
                                m.bytes(), "");
                        counts[0]++;
                        MessageHeader h = m.decoded().header();
                        Stream k = Stream.of(m);
                        Integer channel = channels.get(k);
                        if (channel == null) {
                            channel = addChannel(w, registry, k, h, schemas.get(k));
                            channels.put(k, channel);
                        }
                        w.message(channel, m.timeNanos(),
                                PlayerJson.of(h, m.decoded().body()).getBytes(StandardCharsets.UTF_8));
                        counts[1]++;
                        m.toStreamMessage().ifPresent(scene::accept);
                    }
                }
            });
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
        return new Summary(counts[0], counts[1], channels.size(), foxglove.channels(), scene.robots());
    }

    /** Every message of the time range, Player messages only when the filter takes them. */
    private static void forEachTaken(SessionLog log, ExportFilter filter, CodecRegistry registry,
            ExportFilter.MessageAction taken) throws IOException {
        filter.forEachInRange(log, m -> {
            if (m.kind() != LogMessage.Kind.FRAME || filter.takes(m, registry)) {
                taken.accept(m);
            }
        });
    }

    /** The topic of one connection's messages of one kind on a Player port. */
    static String topic(CodecRegistry registry, int port, int conn, MessageHeader h) {
        return "/" + port + "/" + conn + "/" + Names.iface(registry, h.interf()) + ":" + h.index() + "/"
                + Names.type(h.type()) + "/" + Names.subtype(registry, h);
    }

    private static int addChannel(SpyLogWriter w, CodecRegistry registry, Stream k, MessageHeader h, PlayerJsonSchema.Node schema)
            throws IOException {
        String title = "player " + Names.iface(registry, h.interf()) + " " + Names.type(h.type()) + " "
                + Names.subtype(registry, h);
        return w.addChannel(topic(registry, k.port(), k.conn(), h), "json", title.replace(' ', '.'), "jsonschema",
                PlayerJsonSchema.text(title, schema).getBytes(StandardCharsets.UTF_8),
                Map.of("port", Integer.toString(k.port()), "conn", Integer.toString(k.conn()),
                        "interface", Names.iface(registry, k.interf()), "index", Integer.toString(k.index())));
    }
}
