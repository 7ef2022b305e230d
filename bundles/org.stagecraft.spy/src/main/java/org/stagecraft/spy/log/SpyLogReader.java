package org.stagecraft.spy.log;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.PriorityQueue;
import java.util.Set;
import java.util.TreeMap;
import java.util.zip.CRC32;

import org.stagecraft.player.wire.Direction;

import com.github.luben.zstd.Zstd;

/**
 * Reads a spy log written by {@link SpyLogWriter}. A complete file is opened through its summary
 * (chunk index, statistics, channels) without reading the chunks; a file that was cut off (the spy
 * crashed, the disk filled up) or whose summary is damaged is scanned from the start instead, and
 * every complete chunk whose CRC holds is recovered ({@link #recovered()}). Chunks are read and
 * decompressed only when entries are asked for.
 */
public final class SpyLogReader implements AutoCloseable {
    private static final int MAX_RECORD = Integer.MAX_VALUE - 64;

    private record ChannelInfo(int id, String topic, String encoding, boolean events, int conn, int port,
            Direction dir, Map<String, String> metadata) {
        /** Stagecraft's own robot-hold channel (not a wire channel, not in {@link SpyLogReader#entries()}). */
        boolean hold() {
            return Layout.HOLD_ENCODING.equals(encoding) && Layout.TOPIC_HOLD.equals(topic);
        }
    }

    /** A chunk of the file; {@code channels} is null when the file does not say. */
    private record ChunkRef(int seq, long start, long end, long offset, long length, Set<Integer> channels) {
    }

    private final Path path;
    private final FileChannel file;
    private final long size;
    private final Map<Integer, ChannelInfo> channels = new TreeMap<>();
    private final List<ChunkRef> chunks = new ArrayList<>();
    private Map<String, String> metadata = Map.of();
    private long wireCount;
    private long eventCount;
    private long startTime;
    private long endTime;
    private boolean recovered;
    private int skippedChunks;
    private int chunksRead;
    private List<LogConnection> connections;

    private SpyLogReader(Path path, FileChannel file) throws IOException {
        this.path = path;
        this.file = file;
        this.size = file.size();
    }

    /**
     * Opens a spy log: through its summary when the file is complete, else by scanning it (then
     * {@link #recovered()} is true).
     *
     * @throws SpyLogFormatException if the file is not an MCAP file
     */
    public static SpyLogReader open(Path file) throws IOException {
        FileChannel ch = FileChannel.open(file, StandardOpenOption.READ);
        try {
            SpyLogReader r = new SpyLogReader(file, ch);
            r.load();
            return r;
        } catch (IOException | RuntimeException e) {
            ch.close();
            throw e;
        }
    }

    /** True if the file starts with MCAP's magic bytes. */
    public static boolean isMcap(byte[] head) {
        return head.length >= Mcap.MAGIC.length
                && Arrays.equals(head, 0, Mcap.MAGIC.length, Mcap.MAGIC, 0, Mcap.MAGIC.length);
    }

    private void load() throws IOException {
        if (size < Mcap.MAGIC.length || !isMcap(readAt(0, Mcap.MAGIC.length))) {
            throw new SpyLogFormatException(path + ": not an MCAP file (no MCAP magic bytes at its start)");
        }
        Boolean summary;
        try {
            summary = readSummary();
        } catch (SpyLogFormatException e) {
            summary = null; // damaged summary: scan
        }
        if (summary == null || !summary) {
            channels.clear();
            chunks.clear();
            metadata = Map.of();
            boolean complete = scan();
            recovered = summary == null || !complete;
        }
    }

    // --- the indexed way -------------------------------------------------------------------------

    /** @return true if the summary was read, false if the file has a footer but no summary, null if no valid footer */
    private Boolean readSummary() throws IOException {
        if (size < Mcap.MAGIC.length + Mcap.TAIL) {
            return null;
        }
        long footerPos = size - Mcap.TAIL;
        byte[] tail = readAt(footerPos, Mcap.TAIL);
        if (!Arrays.equals(tail, Mcap.RECORD_PREFIX + Mcap.FOOTER_CONTENT, Mcap.TAIL, Mcap.MAGIC, 0, 8)
                || tail[0] != Mcap.OP_FOOTER || Mcap.readU64(tail, 1) != Mcap.FOOTER_CONTENT) {
            return null;
        }
        long summaryStart = Mcap.readU64(tail, 9);
        long summaryOffsetStart = Mcap.readU64(tail, 17);
        long crc = new Mcap.In(tail, 25, 4).u32();
        if (summaryStart == 0) {
            return false;
        }
        if (summaryStart < Mcap.MAGIC.length || summaryStart > footerPos || footerPos - summaryStart > MAX_RECORD) {
            throw new SpyLogFormatException("summary start out of the file");
        }
        byte[] sum = readAt(summaryStart, (int) (footerPos - summaryStart));
        if (crc != 0) {
            CRC32 c = new CRC32();
            c.update(sum);
            c.update(tail, 0, 25);
            if (c.getValue() != crc) {
                throw new SpyLogFormatException("summary CRC mismatch");
            }
        }
        long end = summaryOffsetStart != 0 ? summaryOffsetStart : footerPos;
        if (end < summaryStart || end > footerPos) {
            throw new SpyLogFormatException("summary offset start out of the summary");
        }
        Mcap.In in = new Mcap.In(sum, 0, (int) (end - summaryStart));
        boolean statistics = false;
        Map<Integer, Long> counts = Map.of();
        List<long[]> metadataAt = new ArrayList<>();
        while (in.remaining() > 0) {
            int op = in.u8();
            long len = in.u64();
            if (len > in.remaining()) {
                throw new SpyLogFormatException("summary record runs past the summary");
            }
            Mcap.In r = new Mcap.In(sum, in.pos(), (int) len);
            switch (op) {
                case Mcap.OP_CHANNEL -> channel(r);
                case Mcap.OP_CHUNK_INDEX -> {
                    long start = r.u64();
                    long stop = r.u64();
                    long offset = r.u64();
                    long length = r.u64();
                    int mapLen = r.length32();
                    Set<Integer> ids = new HashSet<>();
                    Mcap.In m = new Mcap.In(sum, r.pos(), mapLen);
                    while (m.remaining() > 0) {
                        ids.add(m.u16());
                        m.u64();
                    }
                    r.skip(mapLen);
                    if (offset < Mcap.MAGIC.length || length > size || offset > size - length) {
                        throw new SpyLogFormatException("chunk index points outside the file");
                    }
                    chunks.add(new ChunkRef(chunks.size(), start, stop, offset, length, ids.isEmpty() ? null : ids));
                }
                case Mcap.OP_STATISTICS -> {
                    r.u64(); // message count (events included)
                    r.u16();
                    r.u32();
                    r.u32();
                    r.u32();
                    r.u32();
                    startTime = r.u64();
                    endTime = r.u64();
                    int mapLen = r.length32();
                    Mcap.In m = new Mcap.In(sum, r.pos(), mapLen);
                    counts = new LinkedHashMap<>();
                    while (m.remaining() > 0) {
                        counts.put(m.u16(), m.u64());
                    }
                    statistics = true;
                }
                case Mcap.OP_METADATA_INDEX -> {
                    long offset = r.u64();
                    long length = r.u64();
                    metadataAt.add(new long[] { offset, length });
                }
                default -> {
                    // schemas, summary offsets, unknown records: not needed
                }
            }
            in.skip((int) len);
        }
        if (!statistics) {
            return false; // another writer's file: count by scanning
        }
        for (Map.Entry<Integer, Long> e : counts.entrySet()) {
            ChannelInfo c = channels.get(e.getKey());
            if (c != null && c.events()) {
                eventCount += e.getValue();
            } else if (c != null && c.dir() != null) {
                wireCount += e.getValue();
            }
        }
        for (long[] m : metadataAt) {
            if (m[1] < Mcap.RECORD_PREFIX || m[1] > MAX_RECORD || m[0] > size - m[1]) {
                throw new SpyLogFormatException("metadata index points outside the file");
            }
            byte[] rec = readAt(m[0], (int) m[1]);
            if (rec[0] != Mcap.OP_METADATA) {
                throw new SpyLogFormatException("metadata index does not point at a metadata record");
            }
            metadata(new Mcap.In(rec, Mcap.RECORD_PREFIX, rec.length - Mcap.RECORD_PREFIX));
        }
        return true;
    }

    // --- the recovering way ----------------------------------------------------------------------

    /** Reads the file record by record; @return true if it reached the Data End record. */
    private boolean scan() throws IOException {
        long pos = Mcap.MAGIC.length;
        long start = Long.MAX_VALUE;
        long stop = Long.MIN_VALUE;
        while (pos + Mcap.RECORD_PREFIX <= size) {
            byte[] pre = readAt(pos, Mcap.RECORD_PREFIX);
            int op = pre[0] & 0xff;
            long len = Mcap.readU64(pre, 1);
            if (len > size - pos - Mcap.RECORD_PREFIX || len > MAX_RECORD) {
                // cut off inside this record: the times still come from the chunks recovered so far
                startTime = chunks.isEmpty() ? 0 : start;
                endTime = chunks.isEmpty() ? 0 : stop;
                return false;
            }
            long body = pos + Mcap.RECORD_PREFIX;
            switch (op) {
                case Mcap.OP_CHUNK -> {
                    byte[] rec = readAt(body, (int) len);
                    Set<Integer> ids = new HashSet<>();
                    long[] times = { Long.MAX_VALUE, Long.MIN_VALUE };
                    try {
                        byte[] records = decompress(rec);
                        records(records, (op2, r) -> {
                            if (op2 == Mcap.OP_CHANNEL) {
                                channel(r);
                            } else if (op2 == Mcap.OP_MESSAGE) {
                                int ch = r.u16();
                                r.u32();
                                long t = r.u64();
                                ids.add(ch);
                                times[0] = Math.min(times[0], t);
                                times[1] = Math.max(times[1], t);
                                ChannelInfo c = channels.get(ch);
                                if (c == null) {
                                    throw new SpyLogFormatException("message on an undefined channel " + ch);
                                }
                                if (c.events()) {
                                    eventCount++;
                                } else if (c.dir() != null) {
                                    wireCount++;
                                }
                            }
                        });
                    } catch (SpyLogFormatException e) {
                        skippedChunks++; // damaged chunk: its messages are lost, the others are not
                        pos = body + len;
                        continue;
                    }
                    if (!ids.isEmpty()) {
                        chunks.add(new ChunkRef(chunks.size(), times[0], times[1], pos, Mcap.RECORD_PREFIX + len, ids));
                        start = Math.min(start, times[0]);
                        stop = Math.max(stop, times[1]);
                    }
                }
                case Mcap.OP_CHANNEL -> channel(new Mcap.In(readAt(body, (int) len), 0, (int) len));
                case Mcap.OP_METADATA -> metadata(new Mcap.In(readAt(body, (int) len), 0, (int) len));
                case Mcap.OP_DATA_END, Mcap.OP_FOOTER -> {
                    startTime = chunks.isEmpty() ? 0 : start;
                    endTime = chunks.isEmpty() ? 0 : stop;
                    return true;
                }
                default -> {
                    // header, message indexes, unknown records
                }
            }
            pos = body + len;
        }
        startTime = chunks.isEmpty() ? 0 : start;
        endTime = chunks.isEmpty() ? 0 : stop;
        return false;
    }

    // --- records ---------------------------------------------------------------------------------

    private interface RecordVisitor {
        void record(int opcode, Mcap.In content) throws SpyLogFormatException;
    }

    private static void records(byte[] records, RecordVisitor v) throws SpyLogFormatException {
        Mcap.In in = new Mcap.In(records, 0, records.length);
        while (in.remaining() > 0) {
            int op = in.u8();
            long len = in.u64();
            if (len > in.remaining()) {
                throw new SpyLogFormatException("record runs past its chunk");
            }
            v.record(op, new Mcap.In(records, in.pos(), (int) len));
            in.skip((int) len);
        }
    }

    private void channel(Mcap.In r) throws SpyLogFormatException {
        int id = r.u16();
        r.u16();
        String topic = r.string();
        String encoding = r.string();
        int mapLen = r.length32();
        Map<String, String> meta = new LinkedHashMap<>();
        Mcap.In m = new Mcap.In(r.array(), r.pos(), mapLen);
        while (m.remaining() > 0) {
            meta.put(m.string(), m.string());
        }
        if (channels.containsKey(id)) {
            return;
        }
        boolean events = Layout.EVENT_ENCODING.equals(encoding) && Layout.TOPIC_EVENTS.equals(topic);
        int conn = -1;
        int port = -1;
        Direction dir = null;
        if (Layout.WIRE_ENCODING.equals(encoding)) {
            try {
                conn = Integer.parseInt(meta.get("conn"));
                port = Integer.parseInt(meta.get("port"));
                dir = Direction.fromLabel(meta.get("dir"));
            } catch (RuntimeException e) {
                throw new SpyLogFormatException("wire channel " + id + " without conn/port/dir metadata", e);
            }
        }
        channels.put(id, new ChannelInfo(id, topic, encoding, events, conn, port, dir, Map.copyOf(meta)));
    }

    private void metadata(Mcap.In r) throws SpyLogFormatException {
        String name = r.string();
        int mapLen = r.length32();
        Map<String, String> meta = new LinkedHashMap<>();
        Mcap.In m = new Mcap.In(r.array(), r.pos(), mapLen);
        while (m.remaining() > 0) {
            meta.put(m.string(), m.string());
        }
        if (Layout.METADATA_SESSION.equals(name)) {
            metadata = Collections.unmodifiableMap(meta);
        }
    }

    /** The chunk's records, decompressed and CRC-checked; {@code rec} is the chunk record's content. */
    private static byte[] decompress(byte[] rec) throws SpyLogFormatException {
        Mcap.In in = new Mcap.In(rec, 0, rec.length);
        in.u64();
        in.u64();
        long rawSize = in.u64();
        long crc = in.u32();
        String compression = in.string();
        long packedSize = in.u64();
        if (packedSize > in.remaining() || rawSize > MAX_RECORD) {
            throw new SpyLogFormatException("chunk sizes out of range");
        }
        byte[] raw;
        switch (compression) {
            case "" -> raw = in.bytes((int) packedSize);
            case "zstd" -> {
                try {
                    raw = Zstd.decompress(Arrays.copyOfRange(rec, in.pos(), in.pos() + (int) packedSize), (int) rawSize);
                } catch (RuntimeException e) {
                    throw new SpyLogFormatException("chunk does not decompress (" + e.getMessage() + ")", e);
                }
            }
            default -> throw new SpyLogFormatException("chunk compression \"" + compression + "\" is not supported");
        }
        if (raw.length != rawSize) {
            throw new SpyLogFormatException("chunk decompressed to " + raw.length + " bytes, expected " + rawSize);
        }
        if (crc != 0) {
            CRC32 c = new CRC32();
            c.update(raw);
            if (c.getValue() != crc) {
                throw new SpyLogFormatException("chunk CRC mismatch");
            }
        }
        return raw;
    }

    private record Item(LogEntry entry, int chunk, int index) {
    }

    /** Every entry of one chunk, in file order. */
    private List<LogEntry> readChunk(ChunkRef c) throws IOException {
        return readChunk(c, null);
    }

    /** The same, and the chunk's robot-hold entries into {@code holds} when it is not null. */
    private List<LogEntry> readChunk(ChunkRef c, List<HoldEntry> holds) throws IOException {
        if (c.length() < Mcap.RECORD_PREFIX || c.length() > MAX_RECORD) {
            throw new SpyLogFormatException("chunk length out of range");
        }
        byte[] rec = readAt(c.offset(), (int) c.length());
        if (rec[0] != Mcap.OP_CHUNK || Mcap.readU64(rec, 1) != c.length() - Mcap.RECORD_PREFIX) {
            throw new SpyLogFormatException(path + ": no chunk at offset " + c.offset());
        }
        chunksRead++;
        byte[] raw;
        try {
            raw = decompress(Arrays.copyOfRange(rec, Mcap.RECORD_PREFIX, rec.length));
        } catch (SpyLogFormatException e) {
            throw new SpyLogFormatException(path + ": chunk at offset " + c.offset() + ": " + e.getMessage(), e);
        }
        List<LogEntry> out = new ArrayList<>();
        records(raw, (op, r) -> {
            if (op == Mcap.OP_CHANNEL) {
                channel(r);
            } else if (op == Mcap.OP_MESSAGE) {
                int ch = r.u16();
                r.u32();
                long t = r.u64();
                r.u64();
                ChannelInfo info = channels.get(ch);
                if (info == null) {
                    throw new SpyLogFormatException("message on an undefined channel " + ch);
                }
                if (holds != null && info.hold()) {
                    holds.add(holdEntry(t, r));
                }
                LogEntry e = entry(info, t, r);
                if (e != null) {
                    out.add(e);
                }
            }
        });
        return out;
    }

    private static HoldEntry holdEntry(long t, Mcap.In r) throws SpyLogFormatException {
        int conn = (int) r.u32();
        int port = (int) r.u32();
        int action = r.u8();
        HoldEntry.Action[] all = HoldEntry.Action.values();
        if (action < 1 || action > all.length) {
            throw new SpyLogFormatException("unknown hold action " + action);
        }
        long programOffset = r.u64();
        long upstreamOffset = r.u64();
        String text = new String(r.bytes(r.u16()), java.nio.charset.StandardCharsets.UTF_8);
        byte[] bytes = r.bytes(r.remaining());
        return new HoldEntry(t, conn, port, all[action - 1], programOffset, upstreamOffset, bytes, text);
    }

    private static LogEntry entry(ChannelInfo c, long t, Mcap.In r) throws SpyLogFormatException {
        if (c.events()) {
            return Layout.event(t, r.array(), r.pos(), r.remaining());
        }
        if (c.dir() == null) {
            return null; // a channel of another tool
        }
        long offset = r.u64();
        LogEntry.Kind kind = Layout.kind(r.u8());
        int reasonLen = r.u16();
        String reason = new String(r.bytes(reasonLen), java.nio.charset.StandardCharsets.UTF_8);
        byte[] bytes = r.bytes(r.remaining());
        return new LogEntry.Wire(t, c.conn(), c.port(), c.dir(), offset, kind, bytes, reason);
    }

    // --- the contract ----------------------------------------------------------------------------

    /** True if the file had no valid footer and summary (cut off, damaged) and was read by scanning it. */
    public boolean recovered() {
        return recovered;
    }

    /** The session metadata given to {@link SpyLogWriter#create}. */
    public Map<String, String> metadata() {
        return metadata;
    }

    /** Every connection, by connection number, from the open and close events. */
    public synchronized List<LogConnection> connections() throws IOException {
        if (connections == null) {
            Map<Integer, LogEntry.Opened> opened = new TreeMap<>();
            Map<Integer, LogEntry.Closed> closed = new TreeMap<>();
            for (ChunkRef c : chunks) {
                if (c.channels() != null && !c.channels().contains(Layout.CHANNEL_EVENTS)) {
                    continue;
                }
                for (LogEntry e : readChunk(c)) {
                    if (e instanceof LogEntry.Opened o) {
                        opened.putIfAbsent(o.conn(), o);
                    } else if (e instanceof LogEntry.Closed x) {
                        closed.putIfAbsent(x.conn(), x);
                    }
                }
            }
            Map<Integer, Integer> ports = new TreeMap<>();
            for (ChannelInfo ci : channels.values()) {
                if (ci.dir() != null) {
                    ports.putIfAbsent(ci.conn(), ci.port());
                }
            }
            Set<Integer> ids = new java.util.TreeSet<>(opened.keySet());
            ids.addAll(closed.keySet());
            ids.addAll(ports.keySet());
            List<LogConnection> list = new ArrayList<>();
            for (int id : ids) {
                LogEntry.Opened o = opened.get(id);
                LogEntry.Closed x = closed.get(id);
                Integer port = ports.get(id);
                list.add(new LogConnection(id, port != null ? port : portOf(o != null ? o.listen() : null),
                        o != null ? o.client() : null, o != null ? o.listen() : null, o != null ? o.upstream() : null,
                        o != null ? o.timeNanos() : -1, x != null ? x.timeNanos() : -1, x != null ? x.reason() : null));
            }
            connections = List.copyOf(list);
        }
        return connections;
    }

    /**
     * Every connection that has wire entries, known from the summary alone (no chunk is read): the
     * wire channels' metadata carries the connection's addresses. Open and close times are not
     * known this way (-1). Empty if a wire channel lacks the addresses (a log written before they
     * were recorded there, or a connection whose open event is not in the log): use
     * {@link #connections()} then.
     */
    public List<LogConnection> indexedConnections() {
        Map<Integer, LogConnection> byConn = new TreeMap<>();
        for (ChannelInfo c : channels.values()) {
            if (c.dir() == null) {
                continue;
            }
            String client = c.metadata().get(Layout.META_CLIENT);
            if (client == null) {
                return List.of();
            }
            byConn.putIfAbsent(c.conn(), new LogConnection(c.conn(), c.port(), client,
                    c.metadata().get(Layout.META_LISTEN), c.metadata().get(Layout.META_UPSTREAM), -1, -1, null));
        }
        return List.copyOf(byConn.values());
    }

    private static int portOf(String address) {
        if (address == null) {
            return -1;
        }
        int colon = address.lastIndexOf(':');
        try {
            return Integer.parseInt(address.substring(colon + 1).trim());
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    /** Log time of the first entry (0 if there is none). */
    public long startTimeNanos() {
        return startTime;
    }

    /** Log time of the last entry (0 if there is none). */
    public long endTimeNanos() {
        return endTime;
    }

    /** Wire entries (banners, Player messages, unframed pieces) in the log; events are not counted. */
    public long messageCount() {
        return wireCount;
    }

    /** Open, close and diagnostic events in the log. */
    public long eventCount() {
        return eventCount;
    }

    /** Chunks in the log (recovered ones only, for a recovered log). */
    public int chunkCount() {
        return chunks.size();
    }

    /** Chunks that were complete but damaged (bad CRC, not decompressible) and skipped while recovering. */
    public int skippedChunks() {
        return skippedChunks;
    }

    /** For tests: offset and length of every chunk record, in file order. */
    List<long[]> chunkSpans() {
        return chunks.stream().sorted(Comparator.comparingLong(ChunkRef::offset))
                .map(c -> new long[] { c.offset(), c.length() }).toList();
    }

    /** For tests: the entries of the chunk at this file offset, in file order. */
    synchronized List<LogEntry> chunkEntries(long offset) throws IOException {
        for (ChunkRef c : chunks) {
            if (c.offset() == offset) {
                return readChunk(c);
            }
        }
        throw new IllegalArgumentException("no chunk at " + offset);
    }

    /** Chunks read and decompressed so far (the index and summary do not count). */
    synchronized int chunksRead() {
        return chunksRead;
    }

    /** Every entry, in log-time order (entries with equal times in the order they were written). */
    public Iterator<LogEntry> entries() {
        return new Merge(chunks, Long.MIN_VALUE);
    }

    /** The entries from the first one at or after {@code timeNanos} on; chunks that end earlier are not read. */
    public Iterator<LogEntry> entriesFrom(long timeNanos) {
        List<ChunkRef> from = chunks.stream().filter(c -> c.end() >= timeNanos).toList();
        return new Merge(from, timeNanos);
    }

    /**
     * The exact byte stream of one direction of one connection: the bytes of its wire entries in stream
     * order. Reads only the chunks that hold that stream.
     *
     * @throws SpyLogFormatException if the entries leave a gap or overlap (a damaged log)
     */
    public synchronized byte[] streamBytes(int conn, Direction dir) throws IOException {
        Set<Integer> wanted = new HashSet<>();
        for (ChannelInfo c : channels.values()) {
            if (c.conn() == conn && c.dir() == dir && !c.events()) {
                wanted.add(c.id());
            }
        }
        List<LogEntry.Wire> pieces = new ArrayList<>();
        if (!wanted.isEmpty()) {
            for (ChunkRef c : chunks) {
                if (c.channels() != null && Collections.disjoint(c.channels(), wanted)) {
                    continue;
                }
                for (LogEntry e : readChunk(c)) {
                    if (e instanceof LogEntry.Wire w && w.conn() == conn && w.dir() == dir) {
                        pieces.add(w);
                    }
                }
            }
        }
        pieces.sort(Comparator.comparingLong(LogEntry.Wire::streamOffset));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        long expected = 0;
        for (LogEntry.Wire w : pieces) {
            if (w.streamOffset() != expected) {
                throw new SpyLogFormatException(path + ": connection " + conn + " " + dir.label() + ": the log has "
                        + (w.streamOffset() > expected ? "no bytes" : "two pieces") + " at stream offset " + expected);
            }
            out.write(w.bytesUnsafe(), 0, w.length());
            expected += w.length();
        }
        return out.toByteArray();
    }

    /**
     * What robot holds did (docs/debugging-robots.md), in the order the spy did it: injections, held-back
     * commands, hold on/off. Empty for a log of a session without holds. These entries are not among
     * {@link #entries()}: that is the program's and Player's traffic exactly as they sent it.
     */
    public synchronized List<HoldEntry> holdEntries() throws IOException {
        List<HoldEntry> out = new ArrayList<>();
        Set<Integer> holdChannels = new HashSet<>();
        for (ChannelInfo c : channels.values()) {
            if (c.hold()) {
                holdChannels.add(c.id());
            }
        }
        if (holdChannels.isEmpty()) {
            return out;
        }
        List<ChunkRef> inFileOrder = new ArrayList<>(chunks);
        inFileOrder.sort(Comparator.comparingLong(ChunkRef::offset));
        for (ChunkRef c : inFileOrder) {
            if (c.channels() == null || !Collections.disjoint(c.channels(), holdChannels)) {
                readChunk(c, out);
            }
        }
        return out;
    }

    /** What the robot program sent on a connection, every byte, including those a hold kept from Player. */
    public byte[] programBytes(int conn) throws IOException {
        return streamBytes(conn, Direction.CLIENT_TO_SERVER);
    }

    /**
     * What Player received on a connection: the program's bytes without those a hold kept back, with
     * the bytes Stagecraft injected, in order. Without holds this is {@link #programBytes}.
     *
     * @throws SpyLogFormatException if the hold entries do not fit the program's stream (a damaged log)
     */
    public byte[] upstreamBytes(int conn) throws IOException {
        byte[] program = programBytes(conn);
        List<HoldEntry> mine = new ArrayList<>();
        for (HoldEntry e : holdEntries()) {
            if (e.conn() == conn && (e.action() == HoldEntry.Action.INJECTED || e.action() == HoldEntry.Action.HELD_BACK)) {
                mine.add(e);
            }
        }
        mine.sort(Comparator.comparingLong(HoldEntry::programOffset)); // stable: injections at one offset keep their order
        ByteArrayOutputStream out = new ByteArrayOutputStream(program.length);
        int pos = 0;
        for (HoldEntry e : mine) {
            if (e.programOffset() < pos || e.programOffset() > program.length) {
                throw new SpyLogFormatException(path + ": connection " + conn + ": hold entry at program offset "
                        + e.programOffset() + " does not fit the program's stream (at " + pos + " of " + program.length + ")");
            }
            out.write(program, pos, (int) e.programOffset() - pos);
            pos = (int) e.programOffset();
            if (out.size() != e.upstreamOffset()) {
                throw new SpyLogFormatException(path + ": connection " + conn + ": " + e.action() + " at upstream offset "
                        + e.upstreamOffset() + ", but the rebuilt stream is at " + out.size());
            }
            if (e.action() == HoldEntry.Action.INJECTED) {
                out.write(e.bytesUnsafe(), 0, e.length());
            } else {
                if (pos + e.length() > program.length
                        || !Arrays.equals(program, pos, pos + e.length(), e.bytesUnsafe(), 0, e.length())) {
                    throw new SpyLogFormatException(path + ": connection " + conn + ": held-back bytes at program offset "
                            + pos + " are not the program's bytes there");
                }
                pos += e.length();
            }
        }
        out.write(program, pos, program.length - pos);
        return out.toByteArray();
    }

    @Override
    public void close() throws IOException {
        file.close();
    }

    // --- merging chunks by time ------------------------------------------------------------------

    /**
     * Merges the chunks' entries by log time. Chunks are taken in order of their first time and read
     * only when the next entry could come from them, so chunks may overlap in time.
     */
    private final class Merge implements Iterator<LogEntry> {
        private final List<ChunkRef> pending;
        private final long from;
        private int next;
        private final PriorityQueue<Item> queue = new PriorityQueue<>(Comparator
                .comparingLong((Item i) -> i.entry().timeNanos()).thenComparingInt(Item::chunk)
                .thenComparingInt(Item::index));

        Merge(List<ChunkRef> chunks, long from) {
            List<ChunkRef> sorted = new ArrayList<>(chunks);
            sorted.sort(Comparator.comparingLong(ChunkRef::start).thenComparingInt(ChunkRef::seq));
            this.pending = sorted;
            this.from = from;
        }

        @Override
        public boolean hasNext() {
            while (true) {
                while (next < pending.size() && (queue.isEmpty()
                        || pending.get(next).start() <= queue.peek().entry().timeNanos())) {
                    ChunkRef c = pending.get(next++);
                    List<LogEntry> entries;
                    try {
                        synchronized (SpyLogReader.this) {
                            entries = readChunk(c);
                        }
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                    for (int i = 0; i < entries.size(); i++) {
                        queue.add(new Item(entries.get(i), c.seq(), i));
                    }
                }
                if (queue.isEmpty()) {
                    return false;
                }
                if (queue.peek().entry().timeNanos() >= from) {
                    return true;
                }
                queue.poll();
            }
        }

        @Override
        public LogEntry next() {
            if (!hasNext()) {
                throw new NoSuchElementException();
            }
            return queue.poll().entry();
        }
    }

    // --- file access -----------------------------------------------------------------------------

    private synchronized byte[] readAt(long pos, int len) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(len);
        while (b.hasRemaining()) {
            int n = file.read(b, pos + b.position());
            if (n < 0) {
                throw new EOFException(path + ": ends at " + (pos + b.position()) + ", expected " + len + " bytes at " + pos);
            }
        }
        return b.array();
    }
}
