package org.stagecraft.mcap;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.FileChannel;
import java.nio.channels.SeekableByteChannel;
import java.nio.channels.WritableByteChannel;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.zip.CRC32;

import com.github.luben.zstd.Zstd;
import com.github.luben.zstd.ZstdCompressCtx;
import org.eclipse.jdt.annotation.Nullable;

/**
 * Writes an MCAP file (https://mcap.dev, major version 0): header, metadata, schemas and channels,
 * messages in zstd-compressed chunks with their message indexes, and at {@link #close()} the data end
 * record, the summary (schemas, channels, statistics, chunk and metadata indexes), summary offsets
 * and the footer, with every CRC the format has.
 *
 * <p>Ids: schemas and channels get ids from 1 in the order they are added. A schema or channel
 * record reaches the file just before the first chunk with a message on it, outside the chunk, so a
 * damaged chunk never takes the definitions of later chunks with it; the summary repeats those used.
 *
 * <p>Crash safety: messages are buffered in the open chunk and reach the file when the chunk is full
 * or at {@link #flush()}, as one write of definitions, chunk and message indexes; a file cut off at
 * any point keeps every complete chunk ({@link McapReader} recovers them). When a write fails (e.g.
 * the disk is full) the method throws, the writer cuts a seekable channel back to its last complete
 * chunk, and every later call throws too.
 *
 * <p>Thread-safe: every method is synchronized except {@link #force()}, which may run beside writing.
 */
public final class McapWriter implements AutoCloseable {
    /** What the header says and how chunks are made. */
    public record Options(String profile, String library, int chunkSize, int zstdLevel) {
        public Options {
            if (chunkSize < 1) {
                throw new IllegalArgumentException("chunk size " + chunkSize);
            }
        }
    }

    private final WritableByteChannel out;
    private final Options options;
    private final CRC32 dataCrc = new CRC32();
    private long position;
    private long lastComplete;
    private @Nullable IOException failure;
    private boolean closed;

    private final List<Schema> schemas = new ArrayList<>(); // id - 1
    private final List<Channel> channels = new ArrayList<>(); // id - 1
    private final Set<Integer> schemaWritten = new HashSet<>();
    private final Set<Integer> channelWritten = new HashSet<>();
    private long[] sequences = new long[16]; // by channel id

    // the open chunk and the definitions to write before it
    private final RecordBuffer definitions = new RecordBuffer(256);
    private final RecordBuffer chunk;
    /**
     * A finished chunk as written (definitions, chunk record, message indexes), compressed straight
     * into it; kept from chunk to chunk with the zstd context, so that writing a chunk allocates
     * no chunk-sized buffers (they were the log's largest source of garbage).
     */
    private final RecordBuffer chunkOut;
    private final CRC32 chunkCrc = new CRC32();
    private @Nullable ZstdCompressCtx zstd;
    private final Map<Integer, long[]> chunkIndex = new LinkedHashMap<>(); // channel -> [n, (time, offset)*]
    private long chunkStart = Long.MAX_VALUE;
    private long chunkEnd = Long.MIN_VALUE;
    private int chunkMessages;
    private int messageAt = -1;

    // summary
    private record ChunkIndexEntry(long start, long end, long offset, long length, Map<Integer, Long> indexOffsets,
            long indexLength, long compressedSize, long uncompressedSize) {
    }

    private record MetadataIndexEntry(long offset, long length, String name) {
    }

    private final List<ChunkIndexEntry> chunkIndexes = new ArrayList<>();
    private final List<MetadataIndexEntry> metadataIndexes = new ArrayList<>();
    private long messageCount;
    private long startTime = Long.MAX_VALUE;
    private long endTime = Long.MIN_VALUE;

    /**
     * Starts a file on any channel (the writer owns it and closes it): magic and header. When the
     * channel is a {@link SeekableByteChannel}, a failed write cuts it back to the last complete chunk;
     * when it is a {@link FileChannel}, {@link #force()} forces it to the device (and {@link #close()} does).
     */
    public McapWriter(WritableByteChannel out, Options options) throws IOException {
        this.out = out;
        this.options = options;
        this.chunk = new RecordBuffer(Math.min(options.chunkSize(), 1 << 20) + 1024);
        this.chunkOut = new RecordBuffer(Math.min(options.chunkSize(), 1 << 20) / 2);
        RecordBuffer b = new RecordBuffer(256);
        b.bytes(Mcap.MAGIC);
        int at = b.begin(Mcap.OP_HEADER);
        b.string(options.profile()).string(options.library());
        b.end(at);
        emit(b);
        lastComplete = position;
    }

    /** A Metadata record (written at once) and its index in the summary. */
    public synchronized void metadata(String name, Map<String, String> values) throws IOException {
        check();
        RecordBuffer b = new RecordBuffer(256);
        int at = b.begin(Mcap.OP_METADATA);
        b.string(name);
        stringMap(b, values == null ? Map.of() : new TreeMap<>(values));
        b.end(at);
        metadataIndexes.add(new MetadataIndexEntry(position, b.size(), name));
        emit(b);
        if (chunkMessages == 0) {
            lastComplete = position;
        }
    }

    /**
     * Adds a schema; an identical one (name, encoding, data) already added is reused.
     *
     * @return its id, for {@link #addChannel}
     */
    public synchronized int addSchema(String name, String encoding, byte[] data) throws IOException {
        check();
        for (Schema s : schemas) {
            if (s.name().equals(name) && s.encoding().equals(encoding) && Arrays.equals(s.data(), data)) {
                return s.id();
            }
        }
        if (schemas.size() >= 0xffff) {
            throw new IOException("more than " + 0xffff + " schemas in one MCAP file");
        }
        Schema s = new Schema(schemas.size() + 1, name, encoding, data);
        schemas.add(s);
        return s.id();
    }

    /**
     * Adds a channel.
     *
     * @param schemaId an id from {@link #addSchema}, or 0 for none
     * @return its id, for {@link #message}
     */
    public synchronized int addChannel(String topic, String messageEncoding, int schemaId, Map<String, String> metadata)
            throws IOException {
        check();
        if (schemaId < 0 || schemaId > schemas.size()) {
            throw new IllegalArgumentException("no schema " + schemaId);
        }
        if (channels.size() >= 0xffff) {
            throw new IOException("more than " + 0xffff + " channels in one MCAP file");
        }
        Channel c = new Channel(channels.size() + 1, schemaId, topic, messageEncoding,
                new TreeMap<>(metadata == null ? Map.of() : metadata));
        channels.add(c);
        if (c.id() >= sequences.length) {
            sequences = Arrays.copyOf(sequences, Math.max(sequences.length * 2, c.id() + 1));
        }
        return c.id();
    }

    /** One message. */
    public synchronized void message(int channel, long logTime, long publishTime, byte[] data) throws IOException {
        beginMessage(channel, logTime, publishTime).bytes(data);
        endMessage();
    }

    /**
     * Starts a message whose data the caller writes into the returned buffer (no copy), then calls
     * {@link #endMessage()}. The caller holds this writer's lock in between (synchronize on it).
     */
    public synchronized RecordBuffer beginMessage(int channel, long logTime, long publishTime) throws IOException {
        check();
        if (messageAt >= 0) {
            throw new IllegalStateException("a message is open");
        }
        if (channel < 1 || channel > channels.size()) {
            throw new IllegalArgumentException("no channel " + channel);
        }
        define(channel);
        long[] idx = chunkIndex.get(channel);
        if (idx == null) {
            idx = new long[1 + 2 * 16];
        } else if (1 + 2 * (idx[0] + 1) > idx.length) {
            idx = Arrays.copyOf(idx, idx.length * 2);
        }
        int n = (int) idx[0];
        idx[1 + 2 * n] = logTime;
        idx[2 + 2 * n] = chunk.size();
        idx[0] = n + 1;
        chunkIndex.put(channel, idx);
        messageAt = chunk.begin(Mcap.OP_MESSAGE);
        long seq = ++sequences[channel];
        chunk.u16(channel).u32(seq).u64(logTime).u64(publishTime);
        chunkStart = Math.min(chunkStart, logTime);
        chunkEnd = Math.max(chunkEnd, logTime);
        startTime = Math.min(startTime, logTime);
        endTime = Math.max(endTime, logTime);
        chunkMessages++;
        messageCount++;
        return chunk;
    }

    /** Ends the message {@link #beginMessage} started; writes the chunk when it is full. */
    public synchronized void endMessage() throws IOException {
        if (messageAt < 0) {
            throw new IllegalStateException("no message is open");
        }
        chunk.end(messageAt);
        messageAt = -1;
        if (chunk.size() >= options.chunkSize()) {
            finishChunk();
        }
    }

    /** Bytes in the file so far (the open chunk is not there yet). */
    public synchronized long bytesWritten() {
        return position;
    }

    /** Messages written so far, on every channel. */
    public synchronized long messageCount() {
        return messageCount;
    }

    /**
     * Writes the open chunk, so that every message so far is in the file (and survives the process
     * being killed); {@link #force()} puts it on the device.
     */
    public synchronized void flush() throws IOException {
        check();
        finishChunk();
    }

    /**
     * Forces what was written to a file to its device (nothing for other channels). Not synchronized
     * with the writing: an fsync can take hundreds of milliseconds on a busy disk, and a writer that
     * waited for it would hold up everything it records, so a caller may force on a thread of its own
     * while writing goes on.
     */
    public void force() throws IOException {
        if (out instanceof FileChannel fc && fc.isOpen()) {
            try {
                fc.force(false);
            } catch (ClosedChannelException e) {
                // closed meanwhile (by close(), or after a failure): nothing left to force
            }
        }
    }

    /** Writes the open chunk, the summary and the footer, and closes the channel. */
    @Override
    public synchronized void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            if (failure != null) {
                throw new IOException("the MCAP file was not finished: " + failure.getMessage(), failure);
            }
            finishChunk();
            writeEnd();
            force();
        } finally {
            if (zstd != null) {
                zstd.close();
                zstd = null;
            }
            out.close();
        }
    }

    // --- chunks ----------------------------------------------------------------------------------

    /** The schema and channel records of a channel, written before the chunk of its first message. */
    private void define(int channel) {
        if (!channelWritten.add(channel)) {
            return;
        }
        Channel c = channels.get(channel - 1);
        if (c.schemaId() != 0 && schemaWritten.add(c.schemaId())) {
            schema(definitions, schemas.get(c.schemaId() - 1));
        }
        channel(definitions, c);
    }

    private void finishChunk() throws IOException {
        if (chunkMessages == 0) {
            return;
        }
        byte[] raw = chunk.array();
        int rawLen = chunk.size();
        chunkCrc.reset();
        chunkCrc.update(raw, 0, rawLen);
        RecordBuffer b = chunkOut;
        b.clear();
        b.bytes(definitions.array(), 0, definitions.size());
        long chunkOffset = position + b.size();
        int at = b.begin(Mcap.OP_CHUNK);
        b.u64(chunkStart).u64(chunkEnd).u64(rawLen).u32(chunkCrc.getValue()).string("zstd");
        int lengthAt = b.size();
        b.u64(0);
        int bound = (int) Zstd.compressBound(rawLen);
        int dataAt = b.reserve(bound);
        int packed;
        try {
            if (zstd == null) {
                zstd = new ZstdCompressCtx().setLevel(options.zstdLevel());
            }
            packed = zstd.compressByteArray(b.array(), dataAt, bound, raw, 0, rawLen);
        } catch (RuntimeException e) { // ZstdException: the message names zstd's error
            throw fail(new IOException("zstd compression failed: " + e.getMessage(), e));
        }
        b.truncate(dataAt + packed);
        b.putU64(lengthAt, packed);
        b.end(at);
        long chunkLength = position + b.size() - chunkOffset;
        Map<Integer, Long> indexOffsets = new LinkedHashMap<>();
        long indexStart = position + b.size();
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
        ChunkIndexEntry ci = new ChunkIndexEntry(chunkStart, chunkEnd, chunkOffset, chunkLength, indexOffsets,
                position + b.size() - indexStart, packed, rawLen);
        emit(b);
        chunkIndexes.add(ci);
        lastComplete = position;
        definitions.clear();
        chunk.clear();
        chunkIndex.clear();
        chunkStart = Long.MAX_VALUE;
        chunkEnd = Long.MIN_VALUE;
        chunkMessages = 0;
    }

    // --- end of file -----------------------------------------------------------------------------

    private void writeEnd() throws IOException {
        RecordBuffer b = new RecordBuffer(4096);
        // Data End: CRC of everything before it (leading magic included)
        long crcValue = dataCrc.getValue();
        int at = b.begin(Mcap.OP_DATA_END);
        b.u32(crcValue);
        b.end(at);
        int sumFrom = b.size();
        long summaryStart = position + sumFrom;
        List<long[]> groups = new ArrayList<>(); // opcode, start, length
        int g = b.size();
        for (Schema s : schemas) {
            if (schemaWritten.contains(s.id())) {
                schema(b, s);
            }
        }
        group(groups, Mcap.OP_SCHEMA, position + g, b.size() - g);
        g = b.size();
        for (Channel c : channels) {
            if (channelWritten.contains(c.id())) {
                channel(b, c);
            }
        }
        group(groups, Mcap.OP_CHANNEL, position + g, b.size() - g);
        g = b.size();
        at = b.begin(Mcap.OP_STATISTICS);
        b.u64(messageCount).u16(schemaWritten.size()).u32(channelWritten.size()).u32(0).u32(metadataIndexes.size())
                .u32(chunkIndexes.size()).u64(messageCount == 0 ? 0 : startTime).u64(messageCount == 0 ? 0 : endTime);
        int map = b.beginU32();
        for (int channel = 1; channel <= channels.size(); channel++) {
            if (sequences[channel] > 0) { // a channel's sequence numbers count its messages
                b.u16(channel).u64(sequences[channel]);
            }
        }
        b.endU32(map);
        b.end(at);
        group(groups, Mcap.OP_STATISTICS, position + g, b.size() - g);
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
        group(groups, Mcap.OP_CHUNK_INDEX, position + g, b.size() - g);
        g = b.size();
        for (MetadataIndexEntry m : metadataIndexes) {
            at = b.begin(Mcap.OP_METADATA_INDEX);
            b.u64(m.offset()).u64(m.length()).string(m.name());
            b.end(at);
        }
        group(groups, Mcap.OP_METADATA_INDEX, position + g, b.size() - g);
        long summaryOffsetStart = position + b.size();
        for (long[] gr : groups) {
            at = b.begin(Mcap.OP_SUMMARY_OFFSET);
            b.u8((int) gr[0]).u64(gr[1]).u64(gr[2]);
            b.end(at);
        }
        boolean anySummary = b.size() > sumFrom;
        b.u8(Mcap.OP_FOOTER).u64(Mcap.FOOTER_CONTENT).u64(anySummary ? summaryStart : 0)
                .u64(anySummary ? summaryOffsetStart : 0);
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

    private static void schema(RecordBuffer b, Schema s) {
        int at = b.begin(Mcap.OP_SCHEMA);
        byte[] data = s.data();
        b.u16(s.id()).string(s.name()).string(s.encoding()).u32(data.length).bytes(data);
        b.end(at);
    }

    private static void channel(RecordBuffer b, Channel c) {
        int at = b.begin(Mcap.OP_CHANNEL);
        b.u16(c.id()).u16(c.schemaId()).string(c.topic()).string(c.messageEncoding());
        stringMap(b, new TreeMap<>(c.metadata()));
        b.end(at);
    }

    private static void stringMap(RecordBuffer b, Map<String, String> m) {
        int at = b.beginU32();
        for (Map.Entry<String, String> e : m.entrySet()) {
            b.string(e.getKey()).string(e.getValue() == null ? "" : e.getValue());
        }
        b.endU32(at);
    }

    // --- output ----------------------------------------------------------------------------------

    private void check() throws IOException {
        if (failure != null) {
            throw new IOException("the MCAP file stopped at its last complete chunk after an earlier error: "
                    + failure.getMessage(), failure);
        }
        if (closed) {
            throw new IOException("the MCAP file is closed");
        }
    }

    private void emit(RecordBuffer b) throws IOException {
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
