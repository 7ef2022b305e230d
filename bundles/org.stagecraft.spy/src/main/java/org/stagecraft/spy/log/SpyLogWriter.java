package org.stagecraft.spy.log;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.SeekableByteChannel;
import java.nio.channels.WritableByteChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.CRC32;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;

import com.github.luben.zstd.Zstd;

/**
 * Writes a spy log: an MCAP file (https://mcap.dev) with one message per framer event (banner, Player
 * message, unframed bytes) on a channel per connection and direction, connection and diagnostic
 * events as JSON on {@code /events}, the session metadata, zstd-compressed chunks with message
 * indexes, and a summary (chunk index, statistics) at {@link #close()}. Layout: docs/spy-log.md.
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
     * Level 1, not zstd's default 3: on recorded Player traffic it compresses twice as fast
     * (~400 vs ~200 MB/s on one core here) to the same ratio (3.06 vs 3.09), and the log writer is
     * the slowest stage of the spy's observation.
     */
    private static final int ZSTD_LEVEL = 1;

    private final WritableByteChannel out;
    private final int chunkSize;
    private final CRC32 dataCrc = new CRC32();
    private long position;
    private long lastComplete;
    private IOException failure;
    private boolean closed;

    // definitions
    private record ChannelDef(int id, int schemaId, String topic, String encoding, Map<String, String> metadata) {
    }

    private record StreamKey(int conn, int port, Direction dir) {
    }

    private final Map<StreamKey, Integer> wireChannels = new HashMap<>();
    private final Map<Integer, ChannelDef> channels = new TreeMap<>();
    private final Map<Integer, Long> sequences = new HashMap<>();
    private final boolean[] schemaWritten = new boolean[3];
    /** Schemas of channels other tools add ({@link #addChannel}), ids after the spy's own. */
    private record SchemaDef(int id, String name, String encoding, byte[] data) {
    }

    private final Map<Integer, SchemaDef> extraSchemas = new TreeMap<>();
    private final java.util.Set<Integer> extraSchemaWritten = new java.util.HashSet<>();
    private int nextExtraChannel = -1;
    /** Stagecraft's hold channel ({@link #hold}), or -1 until the first hold entry. */
    private int holdChannel = -1;
    /** The ids {@link #addChannel} handed out: the only channels {@link #message} writes to. */
    private final java.util.Set<Integer> addedChannels = new java.util.HashSet<>();
    private final java.util.Set<Integer> channelWritten = new java.util.HashSet<>();
    private int nextChannel = Layout.FIRST_WIRE_CHANNEL;
    /** Addresses of each opened connection, repeated in its wire channels' metadata. */
    private final Map<Integer, Map<String, String>> addresses = new HashMap<>();

    // the open chunk
    private final Mcap.Buf chunk;
    private final Map<Integer, long[]> chunkIndex = new LinkedHashMap<>(); // channel -> [n, (time, offset)*]
    private long chunkStart = Long.MAX_VALUE;
    private long chunkEnd = Long.MIN_VALUE;
    private int chunkMessages;

    // summary
    private record ChunkIndexEntry(long start, long end, long offset, long length, Map<Integer, Long> indexOffsets,
            long indexLength, long compressedSize, long uncompressedSize) {
    }

    private record MetadataIndexEntry(long offset, long length, String name) {
    }

    private final List<ChunkIndexEntry> chunkIndexes = new ArrayList<>();
    private final List<MetadataIndexEntry> metadataIndexes = new ArrayList<>();
    private final Map<Integer, Long> channelCounts = new TreeMap<>();
    private long messageCount;
    private long wireCount;
    private long startTime = Long.MAX_VALUE;
    private long endTime = Long.MIN_VALUE;

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
     * a {@link FileChannel}, {@link #flush()} also forces it to the device.
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
        this.out = out;
        this.chunkSize = chunkSize;
        this.chunk = new Mcap.Buf(Math.min(chunkSize, DEFAULT_CHUNK_SIZE) + 1024);
        channels.put(Layout.CHANNEL_EVENTS, new ChannelDef(Layout.CHANNEL_EVENTS, Layout.SCHEMA_EVENT,
                Layout.TOPIC_EVENTS, Layout.EVENT_ENCODING, Map.of()));
        Mcap.Buf b = new Mcap.Buf(256);
        b.bytes(Mcap.MAGIC);
        int at = b.begin(Mcap.OP_HEADER);
        b.string(Layout.PROFILE).string(Layout.LIBRARY);
        b.end(at);
        int metaAt = b.size();
        at = b.begin(Mcap.OP_METADATA);
        b.string(Layout.METADATA_SESSION);
        stringMap(b, metadata == null ? Map.of() : new TreeMap<>(metadata));
        b.end(at);
        metadataIndexes.add(new MetadataIndexEntry(metaAt, b.size() - metaAt, Layout.METADATA_SESSION));
        emit(b);
        lastComplete = position;
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

    /** One framer event (banner, frame or unframed bytes) of a stream: one MCAP message with its exact bytes. */
    public synchronized void wire(long timeNanos, int conn, int port, Direction dir, WireEvent event)
            throws IOException {
        LogEntry.Kind kind;
        String reason = "";
        byte[] bytes;
        switch (event) {
            case WireEvent.Banner b -> {
                kind = LogEntry.Kind.BANNER;
                bytes = b.bytes();
            }
            case WireEvent.Frame f -> {
                kind = LogEntry.Kind.FRAME;
                bytes = f.bytes();
            }
            case WireEvent.Unframed u -> {
                kind = LogEntry.Kind.UNFRAMED;
                bytes = u.bytes();
                reason = u.reason() == null ? "" : u.reason();
            }
        }
        wire(timeNanos, conn, port, dir, event.offset(), kind, bytes, reason);
    }

    /** The same for bytes the caller has already taken apart. */
    public synchronized void wire(long timeNanos, int conn, int port, Direction dir, long streamOffset,
            LogEntry.Kind kind, byte[] bytes, String reason) throws IOException {
        check();
        int channel = wireChannel(conn, port, dir);
        byte[] why = Layout.utf8(reason == null ? "" : reason);
        if (why.length > 0xffff) {
            why = Arrays.copyOf(why, 0xffff);
        }
        int at = beginMessage(channel, timeNanos);
        chunk.u64(streamOffset).u8(Layout.kindCode(kind)).u16(why.length).bytes(why).bytes(bytes);
        endMessage(at);
        wireCount++;
    }

    public synchronized void diagnostic(long timeNanos, int conn, Direction dir, long streamOffset, String text)
            throws IOException {
        event(timeNanos, Layout.diagnostic(conn, dir, streamOffset, text));
    }

    /**
     * Adds a channel of another kind beside the spy's own, e.g. decoded JSON for viewers such as
     * Foxglove. Readers of spy logs skip such channels. A log without added channels is byte for byte
     * what it was before this method existed.
     *
     * @param schemaEncoding e.g. "jsonschema"; with {@code schemaData} empty and encoding "" for no schema
     * @return the channel id to pass to {@link #message}
     */
    public synchronized int addChannel(String topic, String messageEncoding, String schemaName, String schemaEncoding,
            byte[] schemaData, Map<String, String> metadata) throws IOException {
        check();
        int schemaId = 0;
        if (schemaName != null) {
            for (SchemaDef d : extraSchemas.values()) {
                if (d.name().equals(schemaName) && d.encoding().equals(schemaEncoding) && Arrays.equals(d.data(), schemaData)) {
                    schemaId = d.id();
                }
            }
            if (schemaId == 0) {
                schemaId = schemaWritten.length + extraSchemas.size();
                extraSchemas.put(schemaId, new SchemaDef(schemaId, schemaName, schemaEncoding, schemaData.clone()));
            }
        }
        // added channels count down from the top of the id space, so the spy's wire channels keep
        // the ids they would have had without them
        if (nextExtraChannel < 0) {
            nextExtraChannel = 0xffff;
        }
        if (nextExtraChannel < nextChannel) {
            throw new IOException("more than " + (0xffff - 1) + " channels in one spy log");
        }
        int id = nextExtraChannel--;
        addedChannels.add(id);
        channels.put(id, new ChannelDef(id, schemaId, topic, messageEncoding,
                new TreeMap<>(metadata == null ? Map.of() : metadata)));
        return id;
    }

    /** One message on a channel {@link #addChannel} made. */
    public synchronized void message(int channel, long timeNanos, byte[] data) throws IOException {
        check();
        ChannelDef c = channels.get(channel);
        if (c == null || !addedChannels.contains(channel)) {
            throw new IllegalArgumentException("channel " + channel + " was not added with addChannel");
        }
        int at = beginMessage(channel, timeNanos);
        chunk.bytes(data);
        endMessage(at);
    }

    /**
     * Records what a robot hold did: bytes Stagecraft injected towards Player, program bytes it held
     * back, or the hold switching on or off. Goes to Stagecraft's own channel ({@code /stagecraft/hold}),
     * created at the first call, so a log of a session without holds is what it always was.
     */
    public synchronized void hold(HoldEntry e) throws IOException {
        check();
        if (holdChannel < 0) {
            holdChannel = addChannel(Layout.TOPIC_HOLD, Layout.HOLD_ENCODING, Layout.SCHEMA_HOLD_NAME, "", new byte[0],
                    Map.of("stagecraft", "hold"));
        }
        byte[] text = Layout.utf8(e.text());
        if (text.length > 0xffff) {
            text = Arrays.copyOf(text, 0xffff);
        }
        int at = beginMessage(holdChannel, e.timeNanos());
        chunk.u32(e.conn()).u32(e.port()).u8(e.action().ordinal() + 1).u64(e.programOffset()).u64(e.upstreamOffset())
                .u16(text.length).bytes(text).bytes(e.bytesUnsafe());
        endMessage(at);
    }

    /** Wire messages written (banners, Player messages, unframed pieces); events are not counted. */
    public synchronized long messagesWritten() {
        return wireCount;
    }

    /** Bytes in the file so far (the open chunk is not there yet). */
    public synchronized long bytesWritten() {
        return position;
    }

    /** Writes the open chunk, so that everything logged so far is in the file, and forces a file to disk. */
    public synchronized void flush() throws IOException {
        check();
        finishChunk();
        if (out instanceof FileChannel fc) {
            try {
                fc.force(false);
            } catch (IOException e) {
                throw fail(e);
            }
        }
    }

    /** Writes the open chunk, the summary and the footer, and closes the file. */
    @Override
    public synchronized void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            if (failure != null) {
                throw new IOException("the spy log was not finished: " + failure.getMessage(), failure);
            }
            finishChunk();
            writeEnd();
        } finally {
            out.close();
        }
    }

    // --- messages and chunks ---------------------------------------------------------------------

    private void event(long timeNanos, byte[] json) throws IOException {
        check();
        int at = beginMessage(Layout.CHANNEL_EVENTS, timeNanos);
        chunk.bytes(json);
        endMessage(at);
    }

    private int wireChannel(int conn, int port, Direction dir) throws IOException {
        StreamKey key = new StreamKey(conn, port, dir);
        Integer id = wireChannels.get(key);
        if (id == null) {
            if (nextChannel > 0xffff || (nextExtraChannel >= 0 && nextChannel > nextExtraChannel)) {
                throw new IOException("more than " + (0xffff - 1) + " streams in one spy log");
            }
            id = nextChannel++;
            wireChannels.put(key, id);
            channels.put(id, new ChannelDef(id, Layout.SCHEMA_WIRE, Layout.wireTopic(conn, port, dir),
                    Layout.WIRE_ENCODING, new TreeMap<>(Layout.wireChannelMetadata(conn, port, dir,
                            addresses.getOrDefault(conn, Map.of())))));
        }
        return id;
    }

    private int beginMessage(int channel, long time) {
        define(channel);
        long[] idx = chunkIndex.get(channel);
        if (idx == null) {
            idx = new long[1 + 2 * 16];
        } else if (1 + 2 * (idx[0] + 1) > idx.length) {
            idx = Arrays.copyOf(idx, idx.length * 2);
        }
        int n = (int) idx[0];
        idx[1 + 2 * n] = time;
        idx[2 + 2 * n] = chunk.size();
        idx[0] = n + 1;
        chunkIndex.put(channel, idx);
        int at = chunk.begin(Mcap.OP_MESSAGE);
        long seq = sequences.merge(channel, 1L, Long::sum);
        chunk.u16(channel).u32(seq).u64(time).u64(time);
        chunkStart = Math.min(chunkStart, time);
        chunkEnd = Math.max(chunkEnd, time);
        startTime = Math.min(startTime, time);
        endTime = Math.max(endTime, time);
        chunkMessages++;
        messageCount++;
        channelCounts.merge(channel, 1L, Long::sum);
        return at;
    }

    private void endMessage(int at) throws IOException {
        chunk.end(at);
        if (chunk.size() >= chunkSize) {
            finishChunk();
        }
    }

    /** Schema and channel records go into the chunk where the channel is first used. */
    private void define(int channel) {
        if (channelWritten.contains(channel)) {
            return;
        }
        ChannelDef c = channels.get(channel);
        if (c.schemaId() >= schemaWritten.length) {
            if (extraSchemaWritten.add(c.schemaId())) {
                extraSchema(chunk, extraSchemas.get(c.schemaId()));
            }
        } else if (c.schemaId() != 0 && !schemaWritten[c.schemaId()]) {
            schema(chunk, c.schemaId());
            schemaWritten[c.schemaId()] = true;
        }
        channel(chunk, c);
        channelWritten.add(channel);
    }

    private void finishChunk() throws IOException {
        if (chunkMessages == 0) {
            return;
        }
        byte[] raw = chunk.array();
        int rawLen = chunk.size();
        CRC32 crc = new CRC32();
        crc.update(raw, 0, rawLen);
        byte[] packed;
        try {
            packed = Zstd.compress(Arrays.copyOf(raw, rawLen), ZSTD_LEVEL);
        } catch (RuntimeException e) {
            throw fail(new IOException("zstd compression failed: " + e.getMessage(), e));
        }
        Mcap.Buf b = new Mcap.Buf(packed.length + 128 + 32 * chunkIndex.size());
        int at = b.begin(Mcap.OP_CHUNK);
        b.u64(chunkStart).u64(chunkEnd).u64(rawLen).u32(crc.getValue()).string("zstd").u64(packed.length).bytes(packed);
        b.end(at);
        long chunkLength = b.size();
        Map<Integer, Long> indexOffsets = new LinkedHashMap<>();
        for (Map.Entry<Integer, long[]> e : chunkIndex.entrySet()) {
            indexOffsets.put(e.getKey(), position + b.size());
            long[] idx = e.getValue();
            int rec = b.begin(Mcap.OP_MESSAGE_INDEX);
            b.u16(e.getKey());
            int arr = b.beginU32();
            for (int i = 0; i < idx[0]; i++) {
                b.u64(idx[1 + 2 * i]).u64(idx[2 + 2 * i]);
            }
            b.endU32(arr);
            b.end(rec);
        }
        ChunkIndexEntry ci = new ChunkIndexEntry(chunkStart, chunkEnd, position, chunkLength, indexOffsets,
                b.size() - chunkLength, packed.length, rawLen);
        emit(b);
        chunkIndexes.add(ci);
        lastComplete = position;
        chunk.clear();
        chunkIndex.clear();
        chunkStart = Long.MAX_VALUE;
        chunkEnd = Long.MIN_VALUE;
        chunkMessages = 0;
    }

    // --- end of file -----------------------------------------------------------------------------

    private void writeEnd() throws IOException {
        Mcap.Buf b = new Mcap.Buf(4096);
        // Data End: CRC of everything before it (leading magic included)
        long crcValue = dataCrc.getValue();
        int at = b.begin(Mcap.OP_DATA_END);
        b.u32(crcValue);
        b.end(at);
        long summaryStart = position + b.size();
        int sumFrom = b.size();
        List<long[]> groups = new ArrayList<>(); // opcode, start, length
        // schemas
        int g = b.size();
        for (int s = 1; s < schemaWritten.length; s++) {
            if (schemaWritten[s]) {
                schema(b, s);
            }
        }
        for (SchemaDef d : extraSchemas.values()) {
            if (extraSchemaWritten.contains(d.id())) {
                extraSchema(b, d);
            }
        }
        group(groups, Mcap.OP_SCHEMA, summaryStart + g - sumFrom, b.size() - g);
        g = b.size();
        for (ChannelDef c : channels.values()) {
            if (channelWritten.contains(c.id())) {
                channel(b, c);
            }
        }
        group(groups, Mcap.OP_CHANNEL, summaryStart + g - sumFrom, b.size() - g);
        g = b.size();
        at = b.begin(Mcap.OP_STATISTICS);
        int schemas = 0;
        for (boolean s : schemaWritten) {
            schemas += s ? 1 : 0;
        }
        schemas += extraSchemaWritten.size();
        b.u64(messageCount).u16(schemas).u32(channelWritten.size()).u32(0).u32(metadataIndexes.size())
                .u32(chunkIndexes.size()).u64(messageCount == 0 ? 0 : startTime).u64(messageCount == 0 ? 0 : endTime);
        int map = b.beginU32();
        for (Map.Entry<Integer, Long> e : channelCounts.entrySet()) {
            b.u16(e.getKey()).u64(e.getValue());
        }
        b.endU32(map);
        b.end(at);
        group(groups, Mcap.OP_STATISTICS, summaryStart + g - sumFrom, b.size() - g);
        g = b.size();
        for (ChunkIndexEntry c : chunkIndexes) {
            at = b.begin(Mcap.OP_CHUNK_INDEX);
            b.u64(c.start()).u64(c.end()).u64(c.offset()).u64(c.length());
            map = b.beginU32();
            for (Map.Entry<Integer, Long> e : c.indexOffsets().entrySet()) {
                b.u16(e.getKey()).u64(e.getValue());
            }
            b.endU32(map);
            b.u64(c.indexLength()).string("zstd").u64(c.compressedSize()).u64(c.uncompressedSize());
            b.end(at);
        }
        group(groups, Mcap.OP_CHUNK_INDEX, summaryStart + g - sumFrom, b.size() - g);
        g = b.size();
        for (MetadataIndexEntry m : metadataIndexes) {
            at = b.begin(Mcap.OP_METADATA_INDEX);
            b.u64(m.offset()).u64(m.length()).string(m.name());
            b.end(at);
        }
        group(groups, Mcap.OP_METADATA_INDEX, summaryStart + g - sumFrom, b.size() - g);
        long summaryOffsetStart = summaryStart + b.size() - sumFrom;
        for (long[] gr : groups) {
            at = b.begin(Mcap.OP_SUMMARY_OFFSET);
            b.u8((int) gr[0]).u64(gr[1]).u64(gr[2]);
            b.end(at);
        }
        b.u8(Mcap.OP_FOOTER).u64(Mcap.FOOTER_CONTENT).u64(summaryStart).u64(summaryOffsetStart);
        CRC32 summaryCrc = new CRC32();
        summaryCrc.update(b.array(), sumFrom, b.size() - sumFrom);
        b.u32(summaryCrc.getValue());
        b.bytes(Mcap.MAGIC);
        emit(b);
        lastComplete = position;
    }

    private static void group(List<long[]> groups, int opcode, long start, long length) {
        if (length > 0) {
            groups.add(new long[] { opcode, start, length });
        }
    }

    private static void schema(Mcap.Buf b, int id) {
        int at = b.begin(Mcap.OP_SCHEMA);
        b.u16(id);
        if (id == Layout.SCHEMA_WIRE) {
            // no schema language describes Player's XDR; the encoding is named by the channel
            b.string(Layout.SCHEMA_WIRE_NAME).string("").u32(0);
        } else {
            byte[] json = Layout.utf8(Layout.EVENT_SCHEMA_JSON);
            b.string(Layout.SCHEMA_EVENT_NAME).string("jsonschema").u32(json.length).bytes(json);
        }
        b.end(at);
    }

    private static void extraSchema(Mcap.Buf b, SchemaDef d) {
        int at = b.begin(Mcap.OP_SCHEMA);
        b.u16(d.id()).string(d.name()).string(d.encoding()).u32(d.data().length).bytes(d.data());
        b.end(at);
    }

    private static void channel(Mcap.Buf b, ChannelDef c) {
        int at = b.begin(Mcap.OP_CHANNEL);
        b.u16(c.id()).u16(c.schemaId()).string(c.topic()).string(c.encoding());
        stringMap(b, c.metadata());
        b.end(at);
    }

    private static void stringMap(Mcap.Buf b, Map<String, String> m) {
        int at = b.beginU32();
        for (Map.Entry<String, String> e : m.entrySet()) {
            b.string(e.getKey()).string(e.getValue() == null ? "" : e.getValue());
        }
        b.endU32(at);
    }

    // --- output ----------------------------------------------------------------------------------

    private void check() throws IOException {
        if (failure != null) {
            throw new IOException("the spy log stopped at its last complete chunk after an earlier error: "
                    + failure.getMessage(), failure);
        }
        if (closed) {
            throw new IOException("the spy log is closed");
        }
    }

    private void emit(Mcap.Buf b) throws IOException {
        ByteBuffer buf = ByteBuffer.wrap(b.array(), 0, b.size());
        try {
            while (buf.hasRemaining()) {
                int n = out.write(buf);
                if (n < 0) {
                    throw new IOException("the channel refused to write");
                }
            }
        } catch (IOException e) {
            throw fail(e);
        }
        dataCrc.update(b.array(), 0, b.size());
        position += b.size();
    }

    /** Remembers the failure and cuts a seekable file back to its last complete chunk. */
    private IOException fail(IOException e) {
        if (failure == null) {
            failure = e;
        }
        if (out instanceof SeekableByteChannel s) {
            try {
                s.truncate(lastComplete);
            } catch (IOException | RuntimeException ignored) {
                // the reader's recovery skips a partial chunk anyway
            }
        }
        return e;
    }
}
