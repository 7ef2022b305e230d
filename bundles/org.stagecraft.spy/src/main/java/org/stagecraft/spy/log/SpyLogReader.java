package org.stagecraft.spy.log;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Objects;
import java.util.PriorityQueue;
import java.util.Set;
import java.util.TreeMap;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.mcap.Channel;
import org.stagecraft.mcap.ChunkInfo;
import org.stagecraft.mcap.Damage;
import org.stagecraft.mcap.Mcap;
import org.stagecraft.mcap.McapFormatException;
import org.stagecraft.mcap.McapReader;
import org.stagecraft.mcap.Message;
import org.stagecraft.mcap.RecordInput;
import org.stagecraft.mcap.Schema;
import org.stagecraft.player.wire.Direction;

/**
 * Reads a spy log written by {@link SpyLogWriter} (this version's or an earlier one's). The MCAP side
 * (summary, chunks, CRCs, recovery of a file that was cut off or damaged) is {@link McapReader}'s; this
 * class is the layout: which channels are wire streams, events and holds, and what their messages
 * hold. Chunks are read and decompressed only when entries are asked for. A damaged chunk met while
 * reading entries is skipped and listed in {@link #damage()}.
 */
public final class SpyLogReader implements AutoCloseable {

    /** What a channel of the log is to the layout. */
    private enum Role {
        EVENTS, WIRE, OLD_WIRE, HOLD, OLD_HOLD, OTHER
    }

    private record ChannelInfo(int id, String topic, Role role, int conn, int port, @Nullable Direction dir,
            Map<String, String> metadata) {
        boolean wire() {
            return role == Role.WIRE || role == Role.OLD_WIRE;
        }

        boolean hold() {
            return role == Role.HOLD || role == Role.OLD_HOLD;
        }

        boolean events() {
            return role == Role.EVENTS;
        }
    }

    private final Path path;
    private final McapReader mcap;
    private final Map<Integer, ChannelInfo> channels = new TreeMap<>();
    private final List<ChunkInfo> chunks;
    private final Map<String, String> metadata;
    private long wireCount;
    private long eventCount;
    private long undefinedMessages;
    private int chunksRead;
    private @Nullable List<LogConnection> connections;

    private SpyLogReader(Path path, McapReader mcap) throws IOException {
        this.path = path;
        this.mcap = mcap;
        this.chunks = mcap.chunks();
        this.metadata = mcap.metadata().getOrDefault(Layout.METADATA_SESSION, Map.of());
        for (Channel c : mcap.channels().values()) {
            channel(c);
        }
        for (Map.Entry<Integer, Long> e : mcap.messageCounts().entrySet()) {
            @Nullable ChannelInfo c = channels.get(e.getKey());
            if (c == null) {
                undefinedMessages += e.getValue();
            } else if (c.events()) {
                eventCount += e.getValue();
            } else if (c.wire()) {
                wireCount += e.getValue();
            }
        }
    }

    /**
     * Opens a spy log: through its summary when the file is complete, else by scanning it (then
     * {@link #recovered()} is true).
     *
     * @throws SpyLogFormatException if the file is not an MCAP file
     */
    public static SpyLogReader open(Path file) throws IOException {
        McapReader r;
        try {
            r = McapReader.open(file);
        } catch (McapFormatException e) {
            throw new SpyLogFormatException(e.getMessage(), e);
        }
        try {
            return new SpyLogReader(file, r);
        } catch (IOException | RuntimeException e) {
            r.close();
            throw e;
        }
    }

    /** True if the file starts with MCAP's magic bytes. */
    public static boolean isMcap(byte[] head) {
        return Mcap.isMcap(head);
    }

    /** Why a file starting with {@code head} is not MCAP, for people; null when it is (see {@link Mcap#whyNotMcap}). */
    public static @Nullable String whyNotMcap(byte[] head) {
        return Mcap.whyNotMcap(head);
    }

    /** Knows a channel by its encoding and schema (ids are not part of the layout). */
    private void channel(Channel c) throws SpyLogFormatException {
        if (channels.containsKey(c.id())) {
            return;
        }
        Schema schema = c.schemaId() == 0 ? null : mcap.schemas().get(c.schemaId());
        String schemaName = schema == null ? "" : schema.name();
        Role role;
        if (Layout.EVENT_ENCODING.equals(c.messageEncoding()) && Layout.TOPIC_EVENTS.equals(c.topic())) {
            role = Role.EVENTS;
        } else if (Layout.PROTOBUF.equals(c.messageEncoding()) && WireProto.WIRE_MESSAGE.equals(schemaName)) {
            role = Role.WIRE;
        } else if (Layout.OLD_WIRE_ENCODING.equals(c.messageEncoding())) {
            role = Role.OLD_WIRE;
        } else if (Layout.PROTOBUF.equals(c.messageEncoding()) && WireProto.HOLD_ACTION.equals(schemaName)) {
            role = Role.HOLD;
        } else if (Layout.OLD_HOLD_ENCODING.equals(c.messageEncoding()) && Layout.TOPIC_HOLD.equals(c.topic())) {
            role = Role.OLD_HOLD;
        } else {
            role = Role.OTHER;
        }
        int conn = -1;
        int port = -1;
        Direction dir = null;
        if (role == Role.WIRE || role == Role.OLD_WIRE) {
            try {
                conn = Integer.parseInt(c.metadata().get("conn"));
                port = Integer.parseInt(c.metadata().get("port"));
                dir = Direction.fromLabel(c.metadata().get("dir"));
            } catch (RuntimeException e) {
                throw new SpyLogFormatException(path + ": wire channel " + c.id() + " without conn/port/dir metadata", e);
            }
        }
        channels.put(c.id(), new ChannelInfo(c.id(), c.topic(), role, conn, port, dir, c.metadata()));
    }

    private record Item(LogEntry entry, int chunk, int index) {
    }

    /** Every entry of one chunk, in file order. */
    private List<LogEntry> readChunk(ChunkInfo c) throws IOException {
        return readChunk(c, null);
    }

    /** The same, and the chunk's robot-hold entries into {@code holds} when it is not null. */
    private List<LogEntry> readChunk(ChunkInfo c, @Nullable List<HoldEntry> holds) throws IOException {
        chunksRead++;
        List<LogEntry> out = new ArrayList<>();
        try {
            mcap.readChunk(c, m -> {
                @Nullable ChannelInfo info = channels.get(m.channel());
                if (info == null) {
                    Channel defined = mcap.channels().get(m.channel());
                    if (defined == null) {
                        return; // its definition was lost with a damaged part of the file: counted
                    }
                    channel(defined);
                    info = channels.get(m.channel());
                }
                if (holds != null && info.hold()) {
                    holds.add(holdEntry(info, m));
                }
                LogEntry e = entry(info, m);
                if (e != null) {
                    out.add(e);
                }
            });
        } catch (SpyLogFormatException e) {
            throw e;
        } catch (McapFormatException e) {
            throw new SpyLogFormatException(e.getMessage(), e);
        }
        return out;
    }

    private static HoldEntry holdEntry(ChannelInfo c, Message m) throws SpyLogFormatException {
        try {
            return c.role() == Role.OLD_HOLD ? oldHoldEntry(m) : protoHoldEntry(m);
        } catch (SpyLogFormatException e) {
            throw e;
        } catch (McapFormatException e) {
            throw new SpyLogFormatException(e.getMessage(), e);
        }
    }

    private static HoldEntry protoHoldEntry(Message m) throws McapFormatException {
        long[] v = new long[8];
        byte[][] b = new byte[8][];
        WireProto.read(m.in(), new WireProto.FieldVisitor() {
            @Override
            public void varint(int field, long value) {
                if (field < v.length) {
                    v[field] = value;
                }
            }

            @Override
            public void bytes(int field, byte[] array, int offset, int length) {
                if (field < b.length) {
                    b[field] = Arrays.copyOfRange(array, offset, offset + length);
                }
            }
        });
        HoldEntry.Action[] all = HoldEntry.Action.values();
        if (v[3] < 1 || v[3] > all.length) {
            throw new SpyLogFormatException("unknown hold action " + v[3]);
        }
        String text = b[6] == null ? "" : new String(b[6], StandardCharsets.UTF_8);
        return new HoldEntry(m.publishTime(), (int) v[1], (int) v[2], all[(int) v[3] - 1], v[4], v[5], b[7], text);
    }

    private static HoldEntry oldHoldEntry(Message m) throws McapFormatException {
        RecordInput r = m.in();
        int conn = (int) r.u32();
        int port = (int) r.u32();
        int action = r.u8();
        HoldEntry.Action[] all = HoldEntry.Action.values();
        if (action < 1 || action > all.length) {
            throw new SpyLogFormatException("unknown hold action " + action);
        }
        long programOffset = r.u64();
        long upstreamOffset = r.u64();
        String text = new String(r.bytes(r.u16()), StandardCharsets.UTF_8);
        byte[] bytes = r.bytes(r.remaining());
        return new HoldEntry(m.publishTime(), conn, port, all[action - 1], programOffset, upstreamOffset, bytes, text);
    }

    /** The entry of a message: times are log times (non-decreasing in the file's order). */
    private static @Nullable LogEntry entry(ChannelInfo c, Message m) throws IOException {
        long t = m.logTime();
        if (c.events()) {
            return Layout.event(t, m.array(), m.offset(), m.length());
        }
        if (c.role() == Role.OLD_WIRE) {
            RecordInput r = m.in();
            long offset = r.u64();
            LogEntry.Kind kind = Layout.kind(r.u8());
            int reasonLen = r.u16();
            String reason = new String(r.bytes(reasonLen), StandardCharsets.UTF_8);
            byte[] bytes = r.bytes(r.remaining());
            return new LogEntry.Wire(t, c.conn(), c.port(), Objects.requireNonNull(c.dir()), offset, kind, bytes, reason, m.publishTime());
        }
        if (c.role() != Role.WIRE) {
            return null; // a channel of another tool, or holds
        }
        long[] v = new long[3];
        String[] reason = { "" };
        byte[][] bytes = { new byte[0] };
        WireProto.read(m.in(), new WireProto.FieldVisitor() {
            @Override
            public void varint(int field, long value) {
                if (field < v.length) {
                    v[field] = value;
                }
            }

            @Override
            public void bytes(int field, byte[] array, int offset, int length) {
                if (field == 3) {
                    reason[0] = new String(array, offset, length, StandardCharsets.UTF_8);
                } else if (field == 4) {
                    bytes[0] = Arrays.copyOfRange(array, offset, offset + length);
                }
            }
        });
        return new LogEntry.Wire(t, c.conn(), c.port(), Objects.requireNonNull(c.dir()), v[1], Layout.kind((int) v[2]), bytes[0], reason[0],
                m.publishTime());
    }

    // --- the contract ----------------------------------------------------------------------------

    /** True if the file had no valid footer and summary (cut off, damaged) and was read by scanning it. */
    public boolean recovered() {
        return mcap.recovered();
    }

    /**
     * What could not be read, for people: damaged or skipped parts of the file (so far: a damaged
     * chunk found through the index is listed once an entry from it was asked for), and messages on
     * channels whose definitions were lost with them.
     */
    public List<String> damage() {
        List<String> out = new ArrayList<>();
        for (Damage d : mcap.damage()) {
            out.add(d.describe());
        }
        if (undefinedMessages > 0) {
            out.add(undefinedMessages + " messages on channels whose definitions were lost (skipped)");
        }
        return out;
    }

    /**
     * The damaged parts skipped so far, for people, as {@link #damage()} says them but without the
     * cut-off end of a recovered log ({@link #cutOffEnd()}): what is missing from inside the log.
     */
    public List<String> skippedParts() {
        List<String> out = new ArrayList<>();
        for (Damage d : mcap.damage()) {
            if (!d.cutOff()) {
                out.add(d.describe());
            }
        }
        if (undefinedMessages > 0) {
            out.add(undefinedMessages + " messages on channels whose definitions were lost (skipped)");
        }
        return out;
    }

    /**
     * Messages known to be lost with the damaged parts skipped so far (a damaged chunk's messages
     * where its index says how many; messages on channels whose definitions were lost); parts whose
     * count nobody knows (the cut-off end) add nothing here.
     */
    public long messagesLost() {
        long n = undefinedMessages;
        for (Damage d : mcap.damage()) {
            n += Math.max(0, d.messagesLost());
        }
        return n;
    }

    /**
     * The incomplete last record of a file that was cut off (a crash or a full disk in the middle of a
     * write), for people, or null when the file ends after a whole record.
     */
    public @Nullable String cutOffEnd() {
        for (Damage d : mcap.damage()) {
            if (d.cutOff()) {
                return d.describe();
            }
        }
        return null;
    }

    /** The session metadata given to {@link SpyLogWriter#create}. */
    public Map<String, String> metadata() {
        return metadata;
    }

    /** Every connection, by connection number, from the open and close events. */
    public synchronized List<LogConnection> connections() throws IOException {
        List<LogConnection> connections = this.connections;
        if (connections == null) {
            Map<Integer, LogEntry.Opened> opened = new TreeMap<>();
            Map<Integer, LogEntry.Closed> closed = new TreeMap<>();
            for (ChunkInfo c : chunks) {
                if (c.channels() != null && Collections.disjoint(c.channels(), eventChannels())) {
                    continue;
                }
                List<LogEntry> entries;
                try {
                    entries = readChunk(c);
                } catch (SpyLogFormatException damaged) {
                    continue; // listed in damage()
                }
                for (LogEntry e : entries) {
                    if (e instanceof LogEntry.Opened o) {
                        opened.putIfAbsent(o.conn(), o);
                    } else if (e instanceof LogEntry.Closed x) {
                        closed.putIfAbsent(x.conn(), x);
                    }
                }
            }
            Map<Integer, Integer> ports = new TreeMap<>();
            for (ChannelInfo ci : channels.values()) {
                if (ci.wire()) {
                    ports.putIfAbsent(ci.conn(), ci.port());
                }
            }
            Set<Integer> ids = new java.util.TreeSet<>(opened.keySet());
            ids.addAll(closed.keySet());
            ids.addAll(ports.keySet());
            List<LogConnection> list = new ArrayList<>();
            for (int id : ids) {
                LogEntry.@Nullable Opened o = opened.get(id);
                LogEntry.@Nullable Closed x = closed.get(id);
                @Nullable Integer port = ports.get(id);
                list.add(new LogConnection(id, port != null ? port : portOf(o != null ? o.listen() : null),
                        o != null ? o.client() : null, o != null ? o.listen() : null, o != null ? o.upstream() : null,
                        o != null ? o.timeNanos() : -1, x != null ? x.timeNanos() : -1, x != null ? x.reason() : null));
            }
            connections = List.copyOf(list);
            this.connections = connections;
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
            if (!c.wire()) {
                continue;
            }
            @Nullable String client = c.metadata().get(Layout.META_CLIENT);
            if (client == null) {
                return List.of();
            }
            byConn.putIfAbsent(c.conn(), new LogConnection(c.conn(), c.port(), client,
                    c.metadata().get(Layout.META_LISTEN), c.metadata().get(Layout.META_UPSTREAM), -1, -1, null));
        }
        return List.copyOf(byConn.values());
    }

    private static int portOf(@Nullable String address) {
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
        return mcap.startTime();
    }

    /** Log time of the last entry (0 if there is none). */
    public long endTimeNanos() {
        return mcap.endTime();
    }

    private Set<Integer> eventChannels() {
        Set<Integer> ids = new HashSet<>();
        for (ChannelInfo c : channels.values()) {
            if (c.events()) {
                ids.add(c.id());
            }
        }
        return ids;
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

    /** Damaged parts skipped so far (a bad CRC, not decompressible, bytes that are no record); a cut-off end is not counted. */
    public int skippedChunks() {
        return (int) mcap.damage().stream().filter(d -> !d.cutOff()).count();
    }

    /** For tests: offset and length of every chunk record, in file order. */
    List<long[]> chunkSpans() {
        return chunks.stream().sorted(Comparator.comparingLong(ChunkInfo::offset))
                .map(c -> new long[] { c.offset(), c.length() }).toList();
    }

    /** For tests: the entries of the chunk at this file offset, in file order. */
    synchronized List<LogEntry> chunkEntries(long offset) throws IOException {
        for (ChunkInfo c : chunks) {
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
        List<ChunkInfo> from = chunks.stream().filter(c -> c.endTime() >= timeNanos).toList();
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
            if (c.conn() == conn && c.dir() == dir && c.wire()) {
                wanted.add(c.id());
            }
        }
        List<LogEntry.Wire> pieces = new ArrayList<>();
        if (!wanted.isEmpty()) {
            for (ChunkInfo c : chunks) {
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
        List<ChunkInfo> inFileOrder = new ArrayList<>(chunks);
        inFileOrder.sort(Comparator.comparingLong(ChunkInfo::offset));
        for (ChunkInfo c : inFileOrder) {
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
        mcap.close();
    }

    // --- merging chunks by time ------------------------------------------------------------------

    /**
     * Merges the chunks' entries by log time. Chunks are taken in order of their first time and read
     * only when the next entry could come from them, so chunks may overlap in time.
     */
    private final class Merge implements Iterator<LogEntry> {
        private final List<ChunkInfo> pending;
        private final long from;
        private int next;
        private final PriorityQueue<Item> queue = new PriorityQueue<>(Comparator
                .comparingLong((Item i) -> i.entry().timeNanos()).thenComparingInt(Item::chunk)
                .thenComparingInt(Item::index));

        Merge(List<ChunkInfo> chunks, long from) {
            List<ChunkInfo> sorted = new ArrayList<>(chunks);
            sorted.sort(Comparator.comparingLong(ChunkInfo::startTime).thenComparingInt(ChunkInfo::seq));
            this.pending = sorted;
            this.from = from;
        }

        @Override
        public boolean hasNext() {
            while (true) {
                while (next < pending.size() && (queue.isEmpty()
                        || pending.get(next).startTime() <= queue.peek().entry().timeNanos())) {
                    ChunkInfo c = pending.get(next++);
                    List<LogEntry> entries;
                    try {
                        synchronized (SpyLogReader.this) {
                            entries = readChunk(c);
                        }
                    } catch (SpyLogFormatException damaged) {
                        continue; // a damaged chunk: skipped, listed in damage()
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
}
