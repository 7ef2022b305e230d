package org.stagecraft.recording.fuzz;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Random;

import org.stagecraft.player.session.StreamId;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/**
 * Mutated variants of recorded traffic, for fuzzing whatever reads recordings: a window of a
 * recorded trace's records (so framing often starts inside a message), changed by one to three
 * record mutations — bit flips, size fields set to edge values, chunks cut, dropped, duplicated,
 * split, spliced in from another stream or trace, random garbage, records cut off at the end
 * (connections never closed), connection numbers changed — and sometimes by a text mutation of the
 * file itself (truncated, bits flipped, bytes inserted, lines joined). Deterministic for a seed.
 */
public final class TraceMutator {
    /** One variant: the file's bytes and what was done to make it, for failure messages. */
    public record Variant(long number, String description, byte[] file) {
    }

    private record Source(String name, String headerLine, List<TraceRecord> records) {
    }

    /** Payload sizes a hostile or broken peer might announce. */
    private static final long[] EDGE_SIZES = { 0, 1, 3, 4, 39, 40, 41, 65535, 65536, MessageHeader.MAX_PAYLOAD - 1,
            MessageHeader.MAX_PAYLOAD, MessageHeader.MAX_PAYLOAD + 1L, 0x7fffffffL, 0x80000000L, 0xfffffffeL, 0xffffffffL };

    private final List<Source> sources = new ArrayList<>();
    private final Random random;
    private long count;

    /** Reads the given traces (whole) as the material; {@code seed} fixes every choice. */
    public TraceMutator(List<Path> traces, long seed) throws IOException {
        for (Path p : traces) {
            List<TraceRecord> records = new ArrayList<>();
            String header;
            try (TraceReader r = new TraceReader(p)) {
                for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                    if (!(rec instanceof TraceRecord.Header)) {
                        records.add(rec);
                    }
                }
            }
            try (var lines = Files.lines(p)) {
                header = lines.findFirst().orElseThrow();
            }
            sources.add(new Source(p.getFileName().toString(), header, records));
        }
        if (sources.isEmpty()) {
            throw new IllegalArgumentException("no traces to mutate");
        }
        this.random = new Random(seed);
    }

    /** The next variant: a window of at most {@code maxRecords} records, mutated. */
    public Variant next(int maxRecords) {
        long number = ++count;
        Source src = sources.get(random.nextInt(sources.size()));
        int n = Math.min(src.records().size(), 1 + random.nextInt(Math.max(1, maxRecords)));
        int start = random.nextInt(3) == 0 ? 0 : random.nextInt(src.records().size() - n + 1);
        List<TraceRecord> records = new ArrayList<>(src.records().subList(start, start + n));
        StringBuilder what = new StringBuilder(src.name()).append(" records ").append(start).append("..")
                .append(start + n);
        int mutations = 1 + random.nextInt(3);
        for (int i = 0; i < mutations; i++) {
            what.append(", ").append(mutate(records));
        }
        byte[] file = write(src.headerLine(), records);
        if (random.nextInt(5) == 0) {
            TextMutation m = mutateText(file);
            what.append(", ").append(m.what());
            file = m.file();
        }
        return new Variant(number, what.toString(), file);
    }

    private String mutate(List<TraceRecord> records) {
        int chunk = randomChunk(records);
        if (chunk < 0) {
            records.add(garbage(1, 1, Direction.CLIENT_TO_SERVER));
            return "garbage chunk added";
        }
        TraceRecord.Chunk c = (TraceRecord.Chunk) records.get(chunk);
        byte[] d = c.data().clone();
        switch (random.nextInt(12)) {
            case 0, 1 -> {
                int bits = 1 + random.nextInt(8);
                for (int i = 0; i < bits && d.length > 0; i++) {
                    d[random.nextInt(d.length)] ^= (byte) (1 << random.nextInt(8));
                }
                records.set(chunk, with(c, d));
                return bits + " bits flipped in record " + chunk;
            }
            case 2, 3 -> {
                int at = sizeFieldIn(d);
                long size = random.nextInt(4) == 0 ? random.nextLong(1L << 32) : EDGE_SIZES[random.nextInt(EDGE_SIZES.length)];
                if (at < 0) {
                    return "no size field in record " + chunk;
                }
                d[at] = (byte) (size >>> 24);
                d[at + 1] = (byte) (size >>> 16);
                d[at + 2] = (byte) (size >>> 8);
                d[at + 3] = (byte) size;
                records.set(chunk, with(c, d));
                return "size field at " + at + " of record " + chunk + " set to " + size;
            }
            case 4 -> {
                int keep = d.length == 0 ? 0 : random.nextInt(d.length);
                records.set(chunk, with(c, java.util.Arrays.copyOf(d, keep)));
                return "record " + chunk + " cut to " + keep + " of " + d.length + " bytes";
            }
            case 5 -> {
                records.remove(chunk);
                return "record " + chunk + " dropped";
            }
            case 6 -> {
                records.add(chunk, c);
                return "record " + chunk + " duplicated";
            }
            case 7 -> {
                int at = d.length == 0 ? 0 : random.nextInt(d.length + 1);
                records.set(chunk, with(c, java.util.Arrays.copyOfRange(d, 0, at)));
                records.add(chunk + 1, with(c, java.util.Arrays.copyOfRange(d, at, d.length)));
                return "record " + chunk + " split at " + at;
            }
            case 8 -> {
                Source other = sources.get(random.nextInt(sources.size()));
                int from = randomChunk(other.records());
                if (from < 0) {
                    return "nothing to splice";
                }
                byte[] foreign = ((TraceRecord.Chunk) other.records().get(from)).data();
                records.add(chunk, with(c, foreign));
                return "record " + from + " of " + other.name() + " spliced in before record " + chunk;
            }
            case 9 -> {
                records.add(chunk, garbage(c.stream().conn(), c.stream().port(), c.stream().dir()));
                return "garbage spliced in before record " + chunk;
            }
            case 10 -> {
                int keep = random.nextInt(records.size() + 1);
                records.subList(keep, records.size()).clear();
                return "records cut after " + keep + " (connections never closed)";
            }
            default -> {
                int conn = random.nextInt(4) == 0 ? random.nextInt() : c.stream().conn() + random.nextInt(3) - 1;
                records.set(chunk, new TraceRecord.Chunk(c.line(), c.t(), new StreamId(conn, c.stream().port(), c.stream().dir()), d));
                return "record " + chunk + " moved to connection " + conn;
            }
        }
    }

    private int randomChunk(List<TraceRecord> records) {
        for (int tries = 0; tries < 8 && !records.isEmpty(); tries++) {
            int i = random.nextInt(records.size());
            if (records.get(i) instanceof TraceRecord.Chunk) {
                return i;
            }
        }
        for (int i = 0; i < records.size(); i++) {
            if (records.get(i) instanceof TraceRecord.Chunk) {
                return i;
            }
        }
        return -1;
    }

    /** The size field of a header in {@code d}: where type 1..6 and a small interface code suggest one, else anywhere. */
    private int sizeFieldIn(byte[] d) {
        List<Integer> candidates = new ArrayList<>();
        for (int p = 0; p + MessageHeader.SIZE <= d.length; p++) {
            int interf = int32(d, p + 8);
            int type = int32(d, p + 16);
            if (type >= 1 && type <= 6 && interf >= 0 && interf < 256) {
                candidates.add(p + 36);
            }
        }
        if (!candidates.isEmpty()) {
            return candidates.get(random.nextInt(candidates.size()));
        }
        return d.length < 4 ? -1 : random.nextInt(d.length - 3);
    }

    private static int int32(byte[] b, int p) {
        return (b[p] & 0xff) << 24 | (b[p + 1] & 0xff) << 16 | (b[p + 2] & 0xff) << 8 | b[p + 3] & 0xff;
    }

    private TraceRecord.Chunk garbage(int conn, int port, Direction dir) {
        byte[] g = new byte[1 + random.nextInt(4096)];
        random.nextBytes(g);
        return new TraceRecord.Chunk(0, 0, new StreamId(conn, port, dir), g);
    }

    private static TraceRecord.Chunk with(TraceRecord.Chunk c, byte[] data) {
        return new TraceRecord.Chunk(c.line(), c.t(), c.stream(), data);
    }

    private record TextMutation(String what, byte[] file) {
    }

    /** Changes the file's text itself (may break its JSON, its UTF-8 or its lines). */
    private TextMutation mutateText(byte[] file) {
        byte[] t = file.clone();
        switch (random.nextInt(4)) {
            case 0 -> {
                int at = random.nextInt(t.length + 1);
                return new TextMutation("file cut at byte " + at, java.util.Arrays.copyOf(t, at));
            }
            case 1 -> {
                int flips = 1 + random.nextInt(4);
                for (int i = 0; i < flips; i++) {
                    t[random.nextInt(t.length)] ^= (byte) (1 << random.nextInt(8));
                }
                return new TextMutation(flips + " bits of the text flipped", t);
            }
            case 2 -> {
                int at = random.nextInt(t.length + 1);
                ByteArrayOutputStream out = new ByteArrayOutputStream(t.length + 1);
                out.write(t, 0, at);
                out.write(random.nextInt(256));
                out.write(t, at, t.length - at);
                return new TextMutation("a byte inserted into the text at " + at, out.toByteArray());
            }
            default -> {
                List<Integer> newlines = new ArrayList<>();
                for (int i = 0; i < t.length; i++) {
                    if (t[i] == '\n') {
                        newlines.add(i);
                    }
                }
                if (newlines.isEmpty()) {
                    return new TextMutation("no lines to join", t);
                }
                int at = newlines.get(random.nextInt(newlines.size()));
                t[at] = ' ';
                return new TextMutation("two lines joined at byte " + at, t);
            }
        }
    }

    private static byte[] write(String headerLine, List<TraceRecord> records) {
        StringBuilder out = new StringBuilder(headerLine.length() + records.size() * 128).append(headerLine).append('\n');
        for (TraceRecord r : records) {
            switch (r) {
                case TraceRecord.Chunk c -> out.append("{\"t\":").append(c.t()).append(",\"conn\":").append(c.stream().conn())
                        .append(",\"port\":").append(c.stream().port()).append(",\"dir\":\"").append(c.stream().dir().label())
                        .append("\",\"data\":\"").append(Base64.getEncoder().encodeToString(c.data())).append("\"}\n");
                case TraceRecord.Lifecycle l -> out.append("{\"conn\":").append(l.conn()).append(",\"event\":\"")
                        .append(l.event()).append("\",\"t\":").append(l.t()).append(",\"port\":").append(l.port()).append("}\n");
                case TraceRecord.Header h -> {
                    // only the first line is a header; the window never contains one
                }
            }
        }
        return out.toString().getBytes(StandardCharsets.UTF_8);
    }
}
