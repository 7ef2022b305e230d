package org.stagecraft.spy.log;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.SeekableByteChannel;
import java.nio.channels.WritableByteChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.mcap.McapWriter;
import org.stagecraft.mcap.RecordBuffer;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.WireEvent;

/**
 * Writes a spy log: an MCAP file (https://mcap.dev) with one message per framer event (banner, Player
 * message, unframed bytes) on a channel per connection and direction, connection and diagnostic
 * events as JSON on {@code /events}, the session metadata, zstd-compressed chunks with message
 * indexes, and a summary (chunk index, statistics) at {@link #close()}. Layout: docs/spy-log.md. This
 * class is the layout; the MCAP records, chunks, indexes and CRCs are {@link McapWriter}'s.
 *
 * <p>Times: each entry's capture time (the spy's receive time) is the message's publish time, exactly.
 * Its log time is the capture time too, except that it never goes back: entries reach the log from
 * several forwarding threads, a few microseconds out of order, and MCAP readers expect log times in
 * file order to be non-decreasing, so an entry captured before the previous one is logged at the
 * previous one's log time.
 *
 * <p>Crash safety: records are buffered in the current chunk and reach the file when the chunk is full
 * (about 1 MiB uncompressed) or at {@link #flush()}; a file cut off at any point keeps every complete
 * chunk ({@link SpyLogReader} recovers them). When a write fails (e.g. the disk is full) the method
 * throws, the writer cuts the file back to its last complete chunk where it can, and every later call
 * throws too.
 *
 * <p>Thread-safe: every method is synchronized.
 */
public final class SpyLogWriter implements AutoCloseable {
    /** Uncompressed bytes after which a chunk is written. */
    public static final int DEFAULT_CHUNK_SIZE = 1 << 20;
    /**
     * Level -3 (one of zstd's fast levels), not the default 3 or level 1: on chunks of recorded Player
     * traffic it compresses about twice as fast as level 1 (~1.9 vs ~1.0 GB/s on one core here) for a
     * file 9 % larger (ratio 3.14 vs 3.44), and compression was the largest cost of the log thread,
     * the slowest stage of the spy's observation. Any zstd decoder reads the frames.
     */
    private static final int ZSTD_LEVEL = -3;

    private record StreamKey(int conn, int port, Direction dir) {
    }

    private final McapWriter mcap;
    private final int eventChannel;
    private final int wireSchema;
    private final Map<StreamKey, Integer> wireChannels = new HashMap<>();
    /** The spy's own channels (events, wire, hold): not for {@link #message}. */
    private final java.util.Set<Integer> ownChannels = new java.util.HashSet<>();
    /** Stagecraft's hold channel ({@link #hold}), or -1 until the first hold entry. */
    private int holdChannel = -1;
    /** Addresses of each opened connection, repeated in its wire channels' metadata. */
    private final Map<Integer, Map<String, String>> addresses = new HashMap<>();
    private long wireCount;
    /** Wire messages (and their wire bytes) in the open chunk, and in complete chunks in the file. */
    private long openWire;
    private long openWireBytes;
    private long loggedWire;
    private long loggedWireBytes;
    /** {@link McapWriter#bytesWritten()} when the counts above were last settled: it moves only when a chunk is written. */
    private long settledAt;
    /** A frame's header, re-encoded as on the wire (XDR, big-endian) before its payload. */
    private final ByteBuffer headerScratch = ByteBuffer.allocate(MessageHeader.SIZE);
    private long lastLogTime = Long.MIN_VALUE;

    /** Creates (or truncates) {@code file} and writes the header and the session metadata. */
    public static SpyLogWriter create(Path file, Map<String, String> metadata) throws IOException {
        FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING,
                StandardOpenOption.WRITE);
        try {
            return new SpyLogWriter(ch, metadata, DEFAULT_CHUNK_SIZE);
        } catch (IOException | RuntimeException e) {
            ch.close();
            throw e;
        }
    }

    /**
     * Writes a log to any channel (the writer owns it and closes it). When the channel is a
     * {@link SeekableByteChannel}, a failed write cuts it back to the last complete chunk; when it is
     * a {@link FileChannel}, {@link #force()} forces it to the device.
     *
     * @param chunkSize uncompressed bytes after which a chunk is written
     */
    public static SpyLogWriter create(WritableByteChannel out, Map<String, String> metadata, int chunkSize)
            throws IOException {
        return new SpyLogWriter(out, metadata, chunkSize);
    }

    private SpyLogWriter(WritableByteChannel out, Map<String, String> metadata, int chunkSize) throws IOException {
        if (chunkSize < 1) {
            throw new IllegalArgumentException("chunk size " + chunkSize);
        }
        mcap = new McapWriter(out, new McapWriter.Options(Layout.PROFILE, Layout.LIBRARY, chunkSize, ZSTD_LEVEL));
        mcap.metadata(Layout.METADATA_SESSION, metadata);
        int eventSchema = mcap.addSchema(Layout.SCHEMA_EVENT_NAME, "jsonschema", Layout.utf8(Layout.EVENT_SCHEMA_JSON));
        eventChannel = mcap.addChannel(Layout.TOPIC_EVENTS, Layout.EVENT_ENCODING, eventSchema, Map.of());
        ownChannels.add(eventChannel);
        wireSchema = mcap.addSchema(WireProto.WIRE_MESSAGE, Layout.PROTOBUF, WireProto.DESCRIPTOR_SET);
        settledAt = mcap.bytesWritten();
    }

    // --- the contract ----------------------------------------------------------------------------

    public synchronized void connectionOpened(long timeNanos, int conn, String client, String listen, String upstream)
            throws IOException {
        event(timeNanos, Layout.opened(conn, client, listen, upstream));
        addresses.put(conn, Layout.addressMetadata(client, listen, upstream));
    }

    public synchronized void connectionClosed(long timeNanos, int conn, String reason) throws IOException {
        event(timeNanos, Layout.closed(conn, reason));
    }

    /**
     * One framer event (banner, frame or unframed bytes) of a stream: one MCAP message with its exact
     * bytes, written straight from the event into the open chunk (a frame's header is re-encoded
     * there, its payload copied once).
     */
    public synchronized void wire(long timeNanos, int conn, int port, Direction dir, WireEvent event)
            throws IOException {
        switch (event) {
            case WireEvent.Banner b -> wire(timeNanos, conn, port, dir, b.offset(), LogEntry.Kind.BANNER, null, b.raw(),
                    "");
            case WireEvent.Frame f -> wire(timeNanos, conn, port, dir, f.offset(), LogEntry.Kind.FRAME, f.header(),
                    f.payloadUnsafe(), "");
            case WireEvent.Unframed u -> wire(timeNanos, conn, port, dir, u.offset(), LogEntry.Kind.UNFRAMED, null,
                    u.raw(), u.reason() == null ? "" : u.reason());
        }
    }

    /** The same for bytes the caller has already taken apart. */
    public synchronized void wire(long timeNanos, int conn, int port, Direction dir, long streamOffset,
            LogEntry.Kind kind, byte[] bytes, String reason) throws IOException {
        wire(timeNanos, conn, port, dir, streamOffset, kind, null, bytes, reason);
    }

    /** {@code header}, when not null, is re-encoded before {@code bytes} (its payload). */
    private void wire(long timeNanos, int conn, int port, Direction dir, long streamOffset, LogEntry.Kind kind,
            @Nullable MessageHeader header, byte[] bytes, String reason) throws IOException {
        int channel = wireChannel(conn, port, dir);
        synchronized (mcap) {
            RecordBuffer b = mcap.beginMessage(channel, logTime(timeNanos), timeNanos);
            WireProto.uint(b, 1, streamOffset);
            WireProto.uint(b, 2, Layout.kindCode(kind));
            if (reason != null && !reason.isEmpty()) {
                WireProto.string(b, 3, reason);
            }
            if (header == null) {
                WireProto.bytes(b, 4, bytes, 0, bytes.length);
            } else {
                WireProto.tag(b, 4, 2);
                WireProto.varint(b, MessageHeader.SIZE + (long) bytes.length);
                headerScratch.clear();
                headerScratch.putInt(header.host()).putInt(header.robot()).putInt(header.interf())
                        .putInt(header.index()).putInt(header.type()).putInt(header.subtype())
                        .putLong(Double.doubleToRawLongBits(header.timestamp())).putInt(header.seq())
                        .putInt(header.size());
                b.bytes(headerScratch.array(), 0, MessageHeader.SIZE);
                b.bytes(bytes, 0, bytes.length);
            }
            openWire++;
            openWireBytes += bytes.length + (header == null ? 0 : MessageHeader.SIZE);
            try {
                mcap.endMessage();
            } finally {
                settle();
            }
        }
        wireCount++;
    }

    public synchronized void diagnostic(long timeNanos, int conn, @Nullable Direction dir, long streamOffset, String text)
            throws IOException {
        event(timeNanos, Layout.diagnostic(conn, dir, streamOffset, text));
    }

    /**
     * Adds a channel of another kind beside the spy's own, e.g. decoded JSON for viewers such as
     * Foxglove. Readers of spy logs skip such channels. Its id is the next free one (ids are not part
     * of the layout: readers know the spy's channels by topic, encoding and schema).
     *
     * @param schemaEncoding e.g. "jsonschema"; {@code schemaName} null for no schema
     * @return the channel id to pass to {@link #message}
     */
    public synchronized int addChannel(String topic, String messageEncoding, String schemaName, String schemaEncoding,
            byte[] schemaData, Map<String, String> metadata) throws IOException {
        int schemaId = schemaName == null ? 0 : mcap.addSchema(schemaName, schemaEncoding, schemaData);
        return mcap.addChannel(topic, messageEncoding, schemaId, metadata);
    }

    /** One message on a channel {@link #addChannel} made; its log time never goes back, like the spy's entries'. */
    public synchronized void message(int channel, long timeNanos, byte[] data) throws IOException {
        if (ownChannels.contains(channel)) {
            throw new IllegalArgumentException("channel " + channel + " was not added with addChannel");
        }
        try {
            mcap.message(channel, logTime(timeNanos), timeNanos, data);
        } finally {
            settle();
        }
    }

    /**
     * Records what a robot hold did: bytes Stagecraft injected towards Player, program bytes it held
     * back, or the hold switching on or off. Goes to Stagecraft's own channel ({@code /stagecraft/hold}),
     * created at the first call, so a log of a session without holds has no such channel.
     */
    public synchronized void hold(HoldEntry e) throws IOException {
        if (holdChannel < 0) {
            int schema = mcap.addSchema(WireProto.HOLD_ACTION, Layout.PROTOBUF, WireProto.DESCRIPTOR_SET);
            holdChannel = mcap.addChannel(Layout.TOPIC_HOLD, Layout.PROTOBUF, schema, Map.of("stagecraft", "hold"));
            ownChannels.add(holdChannel);
        }
        synchronized (mcap) {
            RecordBuffer b = mcap.beginMessage(holdChannel, logTime(e.timeNanos()), e.timeNanos());
            WireProto.uint(b, 1, e.conn());
            WireProto.uint(b, 2, e.port());
            WireProto.uint(b, 3, e.action().ordinal() + 1);
            WireProto.uint(b, 4, e.programOffset());
            WireProto.uint(b, 5, e.upstreamOffset());
            if (!e.text().isEmpty()) {
                WireProto.string(b, 6, e.text());
            }
            WireProto.bytes(b, 7, e.bytesUnsafe(), 0, e.length());
            try {
                mcap.endMessage();
            } finally {
                settle();
            }
        }
    }

    /** Wire messages written (banners, Player messages, unframed pieces); events are not counted. */
    public synchronized long messagesWritten() {
        return wireCount;
    }

    /**
     * Wire messages in the file so far: in chunks written completely, so that a reader (or its
     * recovery, after a crash or a full disk) reads them. Not those of the open chunk, nor of a chunk
     * whose write failed (cut back from a file).
     */
    public synchronized long messagesLogged() {
        return loggedWire;
    }

    /** The wire bytes (banners, Player messages with their headers, unframed pieces) of {@link #messagesLogged()}. */
    public synchronized long wireBytesLogged() {
        return loggedWireBytes;
    }

    /** Bytes in the file so far (the open chunk is not there yet). */
    public synchronized long bytesWritten() {
        return mcap.bytesWritten();
    }

    /** Writes the open chunk, so that everything logged so far is in the file ({@link #force()}: on the disk). */
    public synchronized void flush() throws IOException {
        try {
            mcap.flush();
        } finally {
            settle();
        }
    }

    /** Forces what was written to the disk; not synchronized with writing (see {@link McapWriter#force()}). */
    public void force() throws IOException {
        mcap.force();
    }

    /** Writes the open chunk, the summary and the footer, and closes the file. */
    @Override
    public synchronized void close() throws IOException {
        try {
            mcap.flush(); // the open chunk, counted before the summary is written
            settle();
        } catch (IOException e) {
            // the writer has failed (now, or before): close says so, and closes the file
        }
        try {
            mcap.close();
        } finally {
            settle();
        }
    }

    // --- messages --------------------------------------------------------------------------------

    /** The log time for an entry captured at {@code captureNanos}: never before the previous entry's. */
    private long logTime(long captureNanos) {
        lastLogTime = Math.max(lastLogTime, captureNanos);
        return lastLogTime;
    }

    private void event(long timeNanos, byte[] json) throws IOException {
        try {
            mcap.message(eventChannel, logTime(timeNanos), timeNanos, json);
        } finally {
            settle();
        }
    }

    /**
     * After every call that may have written a chunk: the file grows only by whole chunks (and the
     * definitions and message indexes written with them), so when it grew, the open chunk's wire
     * messages are in it. A chunk whose write failed is cut back (or left incomplete) and not counted.
     */
    private void settle() {
        long at = mcap.bytesWritten();
        if (at != settledAt) {
            settledAt = at;
            loggedWire += openWire;
            loggedWireBytes += openWireBytes;
            openWire = 0;
            openWireBytes = 0;
        }
    }

    private int wireChannel(int conn, int port, Direction dir) throws IOException {
        StreamKey key = new StreamKey(conn, port, dir);
        Integer id = wireChannels.get(key);
        if (id == null) {
            id = mcap.addChannel(Layout.wireTopic(conn, port, dir), Layout.PROTOBUF, wireSchema,
                    new TreeMap<>(Layout.wireChannelMetadata(conn, port, dir, addresses.getOrDefault(conn, Map.of()))));
            wireChannels.put(key, id);
            ownChannels.add(id);
        }
        return id;
    }
}
