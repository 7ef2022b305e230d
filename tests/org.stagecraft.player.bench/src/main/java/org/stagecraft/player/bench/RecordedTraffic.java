package org.stagecraft.player.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.stagecraft.player.session.StreamId;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/**
 * Every stream of every recorded trace, held in memory as the recv() chunks the recorder saw, so
 * a benchmark measures framing and decoding only, not file or JSON reading.
 */
final class RecordedTraffic {
    /** One direction of one connection: its chunks in order. */
    record Stream_(StreamId id, List<byte[]> chunks) {
    }

    final List<Stream_> streams = new ArrayList<>();
    long bytes;

    static RecordedTraffic load(Path dir) throws IOException {
        RecordedTraffic t = new RecordedTraffic();
        List<Path> traces;
        try (Stream<Path> s = Files.list(dir)) {
            traces = s.filter(p -> p.getFileName().toString().endsWith(".trace.jsonl")).sorted().toList();
        }
        if (traces.isEmpty()) {
            throw new IOException("no *.trace.jsonl files in " + dir);
        }
        for (Path trace : traces) {
            Map<StreamId, List<byte[]>> byStream = new LinkedHashMap<>();
            try (TraceReader r = new TraceReader(trace)) {
                for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                    if (rec instanceof TraceRecord.Chunk c) {
                        byStream.computeIfAbsent(c.stream(), k -> new ArrayList<>()).add(c.data());
                        t.bytes += c.data().length;
                    }
                }
            }
            byStream.forEach((id, chunks) -> t.streams.add(new Stream_(id, chunks)));
        }
        return t;
    }
}
