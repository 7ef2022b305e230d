package org.stagecraft.mcap;

import java.io.EOFException;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.zip.CRC32;

import com.github.luben.zstd.Zstd;

/**
 * Reads an MCAP file. A complete file is opened through its footer and summary (schemas, channels,
 * chunk index, statistics, metadata) without reading a chunk. A file without a valid footer and
 * summary (cut off by a crash or a full disk, or damaged) is scanned from the start instead
 * ({@link #recovered()}): every chunk whose CRC holds is kept, and after a damaged chunk or a record
 * that does not fit, the scan looks for the next record that does (a chunk must decompress to its
 * CRC), so one damaged chunk costs only its own messages. What could not be read is listed in
 * {@link #damage()}, also when a chunk found through the index turns out damaged later.
 */
public final class McapReader implements AutoCloseable {
    private static final int MAX_RECORD = Integer.MAX_VALUE - 64;
    private static final int SCAN_WINDOW = 1 << 20;

    /** Receives the messages of a chunk (in file order) and, to keep them, the definitions met in it. */
    public interface MessageVisitor {
        void message(Message m) throws IOException;
    }

    private final Path path;
    private final FileChannel file;
    private final long size;
    private String profile = "";
    private String library = "";
    private final Map<Integer, Schema> schemas = new TreeMap<>();
    private final Map<Integer, Channel> channels = new TreeMap<>();
    private final List<ChunkInfo> chunks = new ArrayList<>();
    private final Map<String, Map<String, String>> metadata = new LinkedHashMap<>();
    private final Map<Integer, Long> messageCounts = new TreeMap<>();
    private final List<Damage> damage = new ArrayList<>();
    private final Set<Long> damagedChunks = new java.util.HashSet<>();
    private long startTime;
    private long endTime;
    private boolean recovered;
    private boolean complete;

    private McapReader(Path path, FileChannel file) throws IOException {
        this.path = path;
        this.file = file;
        this.size = file.size();
    }

    /**
     * Opens a file: through its summary when it has a valid one, else by scanning it.
     *
     * @throws McapFormatException if the file is not MCAP (no magic bytes)
     */
    public static McapReader open(Path file) throws IOException {
        FileChannel ch = FileChannel.open(file, StandardOpenOption.READ);
        try {
            McapReader r = new McapReader(file, ch);
            r.load();
            return r;
        } catch (IOException | RuntimeException e) {
            ch.close();
            throw e;
        }
    }

    private void load() throws IOException {
        if (size < Mcap.MAGIC.length || !Mcap.isMcap(readAt(0, Mcap.MAGIC.length))) {
            throw new McapFormatException(path + ": not an MCAP file (no MCAP magic bytes at its start)");
        }
        header();
        boolean indexed;
        try {
            indexed = readSummary();
        } catch (McapFormatException e) {
            indexed = false; // damaged summary: scan
        }
        if (!indexed) {
            schemas.clear();
            channels.clear();
            chunks.clear();
            metadata.clear();
            messageCounts.clear();
            scan();
        }
    }

    private void header() {
        try {
            byte[] pre = readAt(Mcap.MAGIC.length, Mcap.RECORD_PREFIX);
            long len = Mcap.u64(pre, 1);
            if (pre[0] == Mcap.OP_HEADER && len <= size - Mcap.MAGIC.length - Mcap.RECORD_PREFIX && len < 1 << 20) {
                RecordInput r = new RecordInput(readAt(Mcap.MAGIC.length + Mcap.RECORD_PREFIX, (int) len), 0, (int) len);
                profile = r.string();
                library = r.string();
            }
        } catch (IOException e) {
            // a damaged header names nothing; the records after it may still be read
        }
    }

    // --- the indexed way -------------------------------------------------------------------------

    /** @return true if a valid footer, summary, statistics and chunk index were read */
    private boolean readSummary() throws IOException {
        if (size < Mcap.MAGIC.length + Mcap.TAIL) {
            return false;
        }
        long footerPos = size - Mcap.TAIL;
        byte[] tail = readAt(footerPos, Mcap.TAIL);
        if (!Arrays.equals(tail, Mcap.RECORD_PREFIX + Mcap.FOOTER_CONTENT, Mcap.TAIL, Mcap.MAGIC, 0, 8)
                || tail[0] != Mcap.OP_FOOTER || Mcap.u64(tail, 1) != Mcap.FOOTER_CONTENT) {
            return false;
        }
        long summaryStart = Mcap.u64(tail, 9);
        long summaryOffsetStart = Mcap.u64(tail, 17);
        long crc = Mcap.u32(tail, 25);
        if (summaryStart == 0) {
            return false;
        }
        if (summaryStart < Mcap.MAGIC.length || summaryStart > footerPos || footerPos - summaryStart > MAX_RECORD) {
            throw new McapFormatException("summary start out of the file");
        }
        byte[] sum = readAt(summaryStart, (int) (footerPos - summaryStart));
        if (crc != 0) {
            CRC32 c = new CRC32();
            c.update(sum);
            c.update(tail, 0, 25);
            if (c.getValue() != crc) {
                throw new McapFormatException("summary CRC mismatch");
            }
        }
        long end = summaryOffsetStart != 0 ? summaryOffsetStart : footerPos;
        if (end < summaryStart || end > footerPos) {
            throw new McapFormatException("summary offset start out of the summary");
        }
        RecordInput in = new RecordInput(sum, 0, (int) (end - summaryStart));
        boolean statistics = false;
        List<long[]> metadataAt = new ArrayList<>();
        while (in.remaining() > 0) {
            int op = in.u8();
            long len = in.u64();
            if (len < 0 || len > in.remaining()) {
                throw new McapFormatException("summary record runs past the summary");
            }
            RecordInput r = new RecordInput(sum, in.pos(), (int) len);
            switch (op) {
                case Mcap.OP_SCHEMA -> schema(r);
                case Mcap.OP_CHANNEL -> channel(r);
                case Mcap.OP_CHUNK_INDEX -> {
                    long start = r.u64();
                    long stop = r.u64();
                    long offset = r.u64();
                    long length = r.u64();
                    int mapLen = r.length32();
                    Map<Integer, Long> indexOffsets = new LinkedHashMap<>();
                    RecordInput m = new RecordInput(sum, r.pos(), mapLen);
                    while (m.remaining() > 0) {
                        indexOffsets.put(m.u16(), m.u64());
                    }
                    r.skip(mapLen);
                    long indexLength = r.u64();
                    if (offset < Mcap.MAGIC.length || length > size || offset > size - length) {
                        throw new McapFormatException("chunk index points outside the file");
                    }
                    chunks.add(new ChunkInfo(chunks.size(), offset, length, start, stop,
                            Collections.unmodifiableSet(new TreeSet<>(indexOffsets.keySet())), null,
                            Map.copyOf(indexOffsets), indexLength));
                }
                case Mcap.OP_STATISTICS -> {
                    r.u64(); // message count
                    r.u16();
                    r.u32();
                    r.u32();
                    r.u32();
                    r.u32();
                    startTime = r.u64();
                    endTime = r.u64();
                    int mapLen = r.length32();
                    RecordInput m = new RecordInput(sum, r.pos(), mapLen);
                    while (m.remaining() > 0) {
                        messageCounts.put(m.u16(), m.u64());
                    }
                    statistics = true;
                }
                case Mcap.OP_METADATA_INDEX -> metadataAt.add(new long[] { r.u64(), r.u64() });
                default -> {
                    // summary offsets, attachment indexes, unknown records: not needed
                }
            }
            in.skip((int) len);
        }
        if (!statistics) {
            return false; // counts are known only by reading every chunk: scan
        }
        chunks.sort(java.util.Comparator.comparingLong(ChunkInfo::offset));
        for (int i = 0; i < chunks.size(); i++) {
            ChunkInfo c = chunks.get(i);
            chunks.set(i, new ChunkInfo(i, c.offset(), c.length(), c.startTime(), c.endTime(), c.channels(), null,
                    c.messageIndexOffsets(), c.messageIndexLength()));
        }
        for (long[] m : metadataAt) {
            if (m[1] < Mcap.RECORD_PREFIX || m[1] > MAX_RECORD || m[0] > size - m[1]) {
                throw new McapFormatException("metadata index points outside the file");
            }
            byte[] rec = readAt(m[0], (int) m[1]);
            if (rec[0] != Mcap.OP_METADATA) {
                throw new McapFormatException("metadata index does not point at a metadata record");
            }
            metadata(new RecordInput(rec, Mcap.RECORD_PREFIX, rec.length - Mcap.RECORD_PREFIX));
        }
        complete = true;
        return true;
    }

    // --- the recovering way ----------------------------------------------------------------------

    /** What a scan keeps of a chunk while checking it. */
    private record Scanned(long start, long end, Map<Integer, Long> counts) {
    }

    /** Reads the file record by record from the start, finding its way past damage. */
    private void scan() throws IOException {
        recovered = true;
        long pos = Mcap.MAGIC.length;
        long start = Long.MAX_VALUE;
        long stop = Long.MIN_VALUE;
        Damage open = null; // the last damage, while message indexes of its chunk may follow
        while (pos < size) {
            String problem = null;
            boolean cutOff = false;
            long next = -1;
            if (pos + Mcap.RECORD_PREFIX > size) {
                problem = "the file ends inside a record's opcode and length (cut off)";
                cutOff = true;
            } else {
                byte[] pre = readAt(pos, Mcap.RECORD_PREFIX);
                int op = pre[0] & 0xff;
                long len = Mcap.u64(pre, 1);
                long body = pos + Mcap.RECORD_PREFIX;
                if (op == 0 || op > Mcap.OP_DATA_END && op < 0x80) {
                    problem = "no record at this offset (opcode " + op + ")";
                } else if (len < 0 || len > size - body || len > MAX_RECORD) {
                    problem = "a record of " + len + " bytes runs past the end of the file (cut off)";
                    cutOff = true;
                } else {
                    next = body + len;
                    try {
                        switch (op) {
                            case Mcap.OP_CHUNK -> {
                                Scanned s = scanChunk(readAt(body, (int) len));
                                chunks.add(new ChunkInfo(chunks.size(), pos, Mcap.RECORD_PREFIX + len, s.start(), s.end(),
                                        Collections.unmodifiableSet(new TreeSet<>(s.counts().keySet())), s.counts(),
                                        Map.of(), 0));
                                s.counts().forEach((k, v) -> messageCounts.merge(k, v, Long::sum));
                                if (!s.counts().isEmpty()) {
                                    start = Math.min(start, s.start());
                                    stop = Math.max(stop, s.end());
                                }
                                open = null;
                            }
                            case Mcap.OP_SCHEMA -> schema(new RecordInput(readAt(body, (int) len), 0, (int) len));
                            case Mcap.OP_CHANNEL -> channel(new RecordInput(readAt(body, (int) len), 0, (int) len));
                            case Mcap.OP_METADATA -> metadata(new RecordInput(readAt(body, (int) len), 0, (int) len));
                            case Mcap.OP_MESSAGE_INDEX -> {
                                if (open != null) {
                                    long n = messageIndexEntries(readAt(body, (int) len));
                                    int i = damage.indexOf(open);
                                    open = new Damage(open.offset(), open.length(), open.reason(),
                                            Math.max(0, open.messagesLost()) + n, false);
                                    damage.set(i, open);
                                }
                            }
                            case Mcap.OP_DATA_END, Mcap.OP_FOOTER -> {
                                next = size; // the summary is not needed: everything was counted
                            }
                            default -> {
                                // header, attachments, unknown records
                            }
                        }
                    } catch (McapFormatException e) {
                        problem = (op == Mcap.OP_CHUNK ? "chunk " + chunks.size() + ": " : "record " + op + ": ")
                                + e.getMessage();
                    }
                }
            }
            if (problem == null) {
                pos = next;
                continue;
            }
            long found = resync(pos + 1);
            long end = found < 0 ? size : found;
            open = new Damage(pos, end - pos, problem, -1, cutOff && found < 0);
            damage.add(open);
            damagedChunks.add(pos);
            pos = end;
        }
        startTime = chunks.isEmpty() || start == Long.MAX_VALUE ? 0 : start;
        endTime = chunks.isEmpty() || stop == Long.MIN_VALUE ? 0 : stop;
    }

    /** Entries of a message index record's array. */
    private static long messageIndexEntries(byte[] rec) throws McapFormatException {
        RecordInput r = new RecordInput(rec, 0, rec.length);
        r.u16();
        return r.length32() / 16;
    }

    private Scanned scanChunk(byte[] rec) throws McapFormatException {
        Map<Integer, Long> counts = new TreeMap<>();
        long[] times = { Long.MAX_VALUE, Long.MIN_VALUE };
        byte[] raw = decompress(rec);
        records(raw, (op, r) -> {
            switch (op) {
                case Mcap.OP_SCHEMA -> schema(r);
                case Mcap.OP_CHANNEL -> channel(r);
                case Mcap.OP_MESSAGE -> {
                    int ch = r.u16();
                    r.u32();
                    long t = r.u64();
                    counts.merge(ch, 1L, Long::sum);
                    times[0] = Math.min(times[0], t);
                    times[1] = Math.max(times[1], t);
                }
                default -> {
                    // other records are not allowed in chunks; a reader skips them
                }
            }
        });
        return new Scanned(times[0], times[1], counts);
    }

    /**
     * The offset of the next record at or after {@code from} that is what it seems: a chunk whose
     * records decompress to its CRC, or a schema, channel, metadata or message index record that
     * parses to exactly its length; -1 if there is none.
     */
    private long resync(long from) throws IOException {
        long p = from;
        while (p + Mcap.RECORD_PREFIX <= size) {
            int want = (int) Math.min(SCAN_WINDOW + 64L, size - p);
            byte[] w = readAt(p, want);
            int last = want == size - p ? want - Mcap.RECORD_PREFIX : want - 64;
            for (int i = 0; i <= last; i++) {
                int op = w[i] & 0xff;
                if (op != Mcap.OP_CHUNK && op != Mcap.OP_CHANNEL && op != Mcap.OP_SCHEMA && op != Mcap.OP_METADATA
                        && op != Mcap.OP_MESSAGE_INDEX && op != Mcap.OP_DATA_END) {
                    continue;
                }
                long at = p + i;
                long len = Mcap.u64(w, i + 1);
                if (len < 0 || len > size - at - Mcap.RECORD_PREFIX || len > MAX_RECORD) {
                    continue;
                }
                if (plausible(op, at, len, w, i)) {
                    return at;
                }
            }
            p += last + 1;
        }
        return -1;
    }

    private boolean plausible(int op, long at, long len, byte[] w, int i) throws IOException {
        try {
            switch (op) {
                case Mcap.OP_CHUNK -> {
                    if (len < Mcap.CHUNK_FIXED || i + Mcap.RECORD_PREFIX + 32 > w.length) {
                        return false;
                    }
                    long compressionLength = Mcap.u32(w, i + Mcap.RECORD_PREFIX + 28);
                    if (compressionLength > 16 || len < Mcap.CHUNK_FIXED + compressionLength) {
                        return false;
                    }
                    byte[] rec = readAt(at + Mcap.RECORD_PREFIX, (int) len);
                    long recordsLength = Mcap.u64(rec, 32 + (int) compressionLength);
                    if (recordsLength != len - Mcap.CHUNK_FIXED - compressionLength) {
                        return false;
                    }
                    decompress(rec);
                    return true;
                }
                case Mcap.OP_DATA_END -> {
                    return len == 4;
                }
                case Mcap.OP_MESSAGE_INDEX -> {
                    if (len < 6) {
                        return false;
                    }
                    byte[] rec = readAt(at + Mcap.RECORD_PREFIX, 6);
                    long n = Mcap.u32(rec, 2);
                    return n == len - 6 && n % 16 == 0;
                }
                default -> {
                    if (len > 1 << 24) {
                        return false;
                    }
                    RecordInput r = new RecordInput(readAt(at + Mcap.RECORD_PREFIX, (int) len), 0, (int) len);
                    if (op == Mcap.OP_CHANNEL) {
                        r.u16();
                        r.u16();
                        utf8(r);
                        utf8(r);
                        r.skip(r.length32());
                    } else if (op == Mcap.OP_SCHEMA) {
                        r.u16();
                        utf8(r);
                        utf8(r);
                        r.skip(r.length32());
                    } else {
                        utf8(r);
                        r.skip(r.length32());
                    }
                    return r.remaining() == 0;
                }
            }
        } catch (McapFormatException e) {
            return false;
        }
    }

    private static void utf8(RecordInput r) throws McapFormatException {
        int n = r.length32();
        try {
            StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(r.array(), r.pos(), n));
        } catch (CharacterCodingException e) {
            throw new McapFormatException("not UTF-8");
        }
        r.skip(n);
    }

    // --- records ---------------------------------------------------------------------------------

    private interface RecordVisitor {
        void record(int opcode, RecordInput content) throws IOException;
    }

    private static void records(byte[] records, RecordVisitor v) throws McapFormatException {
        RecordInput in = new RecordInput(records, 0, records.length);
        while (in.remaining() > 0) {
            int op = in.u8();
            long len = in.u64();
            if (len < 0 || len > in.remaining()) {
                throw new McapFormatException("record runs past its chunk");
            }
            try {
                v.record(op, new RecordInput(records, in.pos(), (int) len));
            } catch (McapFormatException e) {
                throw e;
            } catch (IOException e) {
                throw new McapFormatException(e.getMessage(), e);
            }
            in.skip((int) len);
        }
    }

    private void schema(RecordInput r) throws McapFormatException {
        int id = r.u16();
        String name = r.string();
        String encoding = r.string();
        byte[] data = r.bytes(r.length32());
        synchronized (this) {
            schemas.putIfAbsent(id, new Schema(id, name, encoding, data));
        }
    }

    private void channel(RecordInput r) throws McapFormatException {
        int id = r.u16();
        int schemaId = r.u16();
        String topic = r.string();
        String encoding = r.string();
        Map<String, String> meta = stringMap(r);
        synchronized (this) {
            channels.putIfAbsent(id, new Channel(id, schemaId, topic, encoding, meta));
        }
    }

    private void metadata(RecordInput r) throws McapFormatException {
        String name = r.string();
        metadata.putIfAbsent(name, Collections.unmodifiableMap(stringMap(r)));
    }

    private static Map<String, String> stringMap(RecordInput r) throws McapFormatException {
        int mapLen = r.length32();
        Map<String, String> meta = new LinkedHashMap<>();
        RecordInput m = new RecordInput(r.array(), r.pos(), mapLen);
        while (m.remaining() > 0) {
            meta.put(m.string(), m.string());
        }
        r.skip(mapLen);
        return meta;
    }

    /** The chunk's records, decompressed and CRC-checked; {@code rec} is the chunk record's content. */
    private static byte[] decompress(byte[] rec) throws McapFormatException {
        RecordInput in = new RecordInput(rec, 0, rec.length);
        in.u64();
        in.u64();
        long rawSize = in.u64();
        long crc = in.u32();
        String compression = in.string();
        long packedSize = in.u64();
        if (packedSize < 0 || rawSize < 0 || packedSize > in.remaining() || rawSize > MAX_RECORD) {
            throw new McapFormatException("chunk sizes out of range");
        }
        if (packedSize != in.remaining()) {
            throw new McapFormatException("the chunk's records do not fill its record (a damaged length)");
        }
        byte[] raw;
        switch (compression) {
            case "" -> raw = in.bytes((int) packedSize);
            case "zstd" -> {
                try {
                    raw = new byte[(int) rawSize];
                    long n = Zstd.decompressByteArray(raw, 0, raw.length, rec, in.pos(), (int) packedSize);
                    if (Zstd.isError(n)) {
                        throw new McapFormatException("chunk does not decompress (" + Zstd.getErrorName(n) + ")");
                    }
                    if (n != rawSize) {
                        throw new McapFormatException("chunk decompressed to " + n + " bytes, expected " + rawSize);
                    }
                } catch (RuntimeException e) {
                    throw new McapFormatException("chunk does not decompress (" + e.getMessage() + ")", e);
                }
            }
            default -> throw new McapFormatException("chunk compression \"" + compression + "\" is not supported");
        }
        if (raw.length != rawSize) {
            throw new McapFormatException("chunk decompressed to " + raw.length + " bytes, expected " + rawSize);
        }
        if (crc != 0) {
            CRC32 c = new CRC32();
            c.update(raw);
            if (c.getValue() != crc) {
                throw new McapFormatException("chunk CRC mismatch");
            }
        }
        return raw;
    }

    // --- the contract ----------------------------------------------------------------------------

    /**
     * Visits every message of a chunk in file order (definitions in it are added to
     * {@link #channels()}). A damaged chunk is added to {@link #damage()} (once) and throws.
     *
     * @throws McapFormatException if the chunk is damaged (CRC, compression, a record that does not fit)
     */
    public void readChunk(ChunkInfo c, MessageVisitor visitor) throws IOException {
        byte[] raw;
        try {
            if (c.length() < Mcap.RECORD_PREFIX || c.length() > MAX_RECORD) {
                throw new McapFormatException("chunk length out of range");
            }
            byte[] rec = readAt(c.offset(), (int) c.length());
            if (rec[0] != Mcap.OP_CHUNK || Mcap.u64(rec, 1) != c.length() - Mcap.RECORD_PREFIX) {
                throw new McapFormatException("no chunk record there");
            }
            raw = decompress(Arrays.copyOfRange(rec, Mcap.RECORD_PREFIX, rec.length));
            records(raw, (op, r) -> {
                if (op == Mcap.OP_MESSAGE && r.remaining() < 22) {
                    throw new McapFormatException("message record shorter than its fields");
                }
            });
        } catch (McapFormatException e) {
            damaged(c, e.getMessage());
            throw new McapFormatException(path + ": chunk " + c.seq() + " at offset " + c.offset() + ": " + e.getMessage(), e);
        }
        byte[] chunkRecords = raw;
        records(chunkRecords, (op, r) -> {
            switch (op) {
                case Mcap.OP_SCHEMA -> schema(r);
                case Mcap.OP_CHANNEL -> channel(r);
                case Mcap.OP_MESSAGE -> {
                    int ch = r.u16();
                    long seq = r.u32();
                    long log = r.u64();
                    long pub = r.u64();
                    visitor.message(new Message(ch, seq, log, pub, chunkRecords, r.pos(), r.remaining()));
                }
                default -> {
                    // not allowed in chunks: skipped
                }
            }
        });
    }

    /** Records a damaged chunk found through the index, with its messages lost per its message indexes. */
    private synchronized void damaged(ChunkInfo c, String reason) {
        if (!damagedChunks.add(c.offset())) {
            return;
        }
        long lost = -1;
        if (c.messageIndexLength() > 0 && !c.messageIndexOffsets().isEmpty()) {
            try {
                lost = 0;
                for (long at : c.messageIndexOffsets().values()) {
                    byte[] pre = readAt(at, Mcap.RECORD_PREFIX + 6);
                    if (pre[0] != Mcap.OP_MESSAGE_INDEX) {
                        lost = -1;
                        break;
                    }
                    lost += Mcap.u32(pre, Mcap.RECORD_PREFIX + 2) / 16;
                }
            } catch (IOException e) {
                lost = -1;
            }
        } else if (c.messageCounts() != null) {
            lost = c.messageCounts().values().stream().mapToLong(Long::longValue).sum();
        }
        damage.add(new Damage(c.offset(), c.length(), "chunk " + c.seq() + ": " + reason, lost, false));
    }

    public Path path() {
        return path;
    }

    public String profile() {
        return profile;
    }

    public String library() {
        return library;
    }

    /** True if the file had no valid footer and summary (cut off, damaged) and was read by scanning it. */
    public boolean recovered() {
        return recovered;
    }

    /** True if the file ends with a valid summary and footer (it was closed properly). */
    public boolean complete() {
        return complete;
    }

    /** What could not be read so far: damage found while scanning, and damaged chunks met while reading. */
    public synchronized List<Damage> damage() {
        return List.copyOf(damage);
    }

    public synchronized Map<Integer, Schema> schemas() {
        return Map.copyOf(schemas);
    }

    /** Channels by id: from the summary, or the ones met while scanning. */
    public synchronized Map<Integer, Channel> channels() {
        return Collections.unmodifiableMap(new TreeMap<>(channels));
    }

    /** The chunks, in file order (recovered ones only, for a recovered file). */
    public List<ChunkInfo> chunks() {
        return Collections.unmodifiableList(chunks);
    }

    /** Metadata records by name. */
    public Map<String, Map<String, String>> metadata() {
        return Collections.unmodifiableMap(metadata);
    }

    /** Messages per channel: the statistics, or what the scan counted. */
    public Map<Integer, Long> messageCounts() {
        return Collections.unmodifiableMap(messageCounts);
    }

    /** Earliest log time (0 without messages). */
    public long startTime() {
        return startTime;
    }

    /** Latest log time (0 without messages). */
    public long endTime() {
        return endTime;
    }

    public long size() {
        return size;
    }

    @Override
    public void close() throws IOException {
        file.close();
    }

    private byte[] readAt(long pos, int len) throws IOException {
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
