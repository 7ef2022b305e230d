package org.stagecraft.spy.bench;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.locks.LockSupport;

import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.recording.trace.TraceCorpus;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.recording.trace.TraceRecord;

/**
 * One recorded connection with the time of every chunk, to be replayed at the recorded pace: each
 * side sends its chunks at the times they were recorded (relative to the connection's first chunk),
 * which is the rate a real robot and a real Player produce. Cut after {@code seconds}.
 */
record TimedSession(List<Double> clientTimes, List<byte[]> clientChunks, List<Double> serverTimes, List<byte[]> serverChunks) {

    /** The first {@code n} connections of the trace corpus, in trace order, cut after {@code seconds}. */
    static List<TimedSession> load(int n, double seconds) throws IOException {
        List<TimedSession> all = new ArrayList<>();
        for (Path trace : TraceCorpus.all()) {
            Map<Integer, List<TraceRecord.Chunk>> byConn = new LinkedHashMap<>();
            try (TraceReader r = new TraceReader(trace)) {
                for (TraceRecord rec = r.next(); rec != null; rec = r.next()) {
                    if (rec instanceof TraceRecord.Chunk c) {
                        byConn.computeIfAbsent(c.stream().conn(), k -> new ArrayList<>()).add(c);
                    }
                }
            }
            for (List<TraceRecord.Chunk> chunks : byConn.values()) {
                all.add(of(chunks, seconds));
            }
        }
        List<TimedSession> picked = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            picked.add(all.get(i % all.size()));
        }
        return picked;
    }

    private static TimedSession of(List<TraceRecord.Chunk> chunks, double seconds) {
        double t0 = chunks.get(0).t();
        List<Double> ct = new ArrayList<>();
        List<byte[]> cc = new ArrayList<>();
        List<Double> st = new ArrayList<>();
        List<byte[]> sc = new ArrayList<>();
        for (TraceRecord.Chunk c : chunks) {
            double t = c.t() - t0;
            if (t > seconds) {
                break;
            }
            boolean client = c.stream().dir() == Direction.CLIENT_TO_SERVER;
            (client ? ct : st).add(t);
            (client ? cc : sc).add(c.data());
        }
        return new TimedSession(ct, cc, st, sc);
    }

    byte[] bytes(Direction dir) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        (dir == Direction.CLIENT_TO_SERVER ? clientChunks : serverChunks).forEach(out::writeBytes);
        return out.toByteArray();
    }

    long totalBytes() {
        return bytes(Direction.CLIENT_TO_SERVER).length + bytes(Direction.SERVER_TO_CLIENT).length;
    }

    /** Player messages in both directions (what "per message" means in the figures). */
    long messages() {
        long n = 0;
        for (Direction d : Direction.values()) {
            long[] frames = {0};
            PlayerFramer f = new PlayerFramer(d, e -> frames[0] += e instanceof WireEvent.Frame ? 1 : 0);
            f.accept(bytes(d));
            f.end();
            n += frames[0];
        }
        return n;
    }

    /**
     * Plays one side at the recorded pace on a connected socket and reads the other side; true when
     * what was received is exactly what the other side recorded.
     */
    boolean play(Socket s, Direction side) throws IOException {
        List<Double> times = side == Direction.CLIENT_TO_SERVER ? clientTimes : serverTimes;
        List<byte[]> chunks = side == Direction.CLIENT_TO_SERVER ? clientChunks : serverChunks;
        byte[] expected = bytes(side == Direction.CLIENT_TO_SERVER ? Direction.SERVER_TO_CLIENT : Direction.CLIENT_TO_SERVER);
        try (s) {
            s.setTcpNoDelay(true);
            OutputStream out = s.getOutputStream();
            CompletableFuture<Void> sending = CompletableFuture.runAsync(() -> {
                long start = System.nanoTime();
                try {
                    for (int i = 0; i < chunks.size(); i++) {
                        long due = start + (long) (times.get(i) * 1e9);
                        for (long wait = due - System.nanoTime(); wait > 0; wait = due - System.nanoTime()) {
                            LockSupport.parkNanos(wait); // pacing, as the recorded robot and Player did
                        }
                        out.write(chunks.get(i));
                    }
                    s.shutdownOutput();
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
            }, r -> Thread.ofVirtual().start(r));
            InputStream in = s.getInputStream();
            byte[] got = in.readAllBytes();
            sending.join();
            return Arrays.equals(got, expected);
        }
    }
}
