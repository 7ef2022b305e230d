package org.stagecraft.spy.proxy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.WritableByteChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.WireEvent;
import org.stagecraft.spy.ForwardingFileChannel;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.log.SpyLogWriter;

/** The spy log is written on a thread of its own, in call order, with bounded memory and failures reported. */
class LogRecorderTest {
    private static final ConnectionInfo CONN = new ConnectionInfo(1, 6665, "127.0.0.1:40000", "127.0.0.1:6665",
            "127.0.0.1:7665");

    @TempDir
    Path dir;

    /** A file channel that remembers which threads wrote to it and can be made to wait or fail. */
    private static final class WatchedChannel implements WritableByteChannel {
        final FileChannel file;
        final Set<String> writers = ConcurrentHashMap.newKeySet();
        volatile CountDownLatch gate;
        volatile long failAfter = Long.MAX_VALUE;
        long written;

        WatchedChannel(Path p) throws IOException {
            file = FileChannel.open(p, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING);
        }

        @Override
        public int write(ByteBuffer src) throws IOException {
            writers.add(Thread.currentThread().getName());
            CountDownLatch g = gate;
            if (g != null) {
                try {
                    g.await(30, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            if (written + src.remaining() > failAfter) {
                throw new IOException("No space left on device");
            }
            int n = file.write(src);
            written += n;
            return n;
        }

        @Override
        public boolean isOpen() {
            return file.isOpen();
        }

        @Override
        public void close() throws IOException {
            file.close();
        }
    }

    /** A file whose force to the disk hangs until released (a busy disk's fsync), and says who forced it. */
    private static final class SlowSyncFile extends ForwardingFileChannel {
        final CountDownLatch forcing = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);
        final Set<String> forcers = ConcurrentHashMap.newKeySet();

        SlowSyncFile(Path p) throws IOException {
            super(FileChannel.open(p, StandardOpenOption.CREATE, StandardOpenOption.WRITE, StandardOpenOption.READ,
                    StandardOpenOption.TRUNCATE_EXISTING));
        }

        @Override
        public void force(boolean metaData) throws IOException {
            forcers.add(Thread.currentThread().getName());
            forcing.countDown();
            try {
                release.await(30, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            file.force(metaData);
        }
    }

    @Test
    void aSlowForceToTheDiskHoldsUpNeitherTheLogThreadNorItsCaller() throws Exception {
        Path log = dir.resolve("slow-sync.mcap");
        SlowSyncFile ch = new SlowSyncFile(log);
        LogRecorder r = new LogRecorder(SpyLogWriter.create(ch, Map.of(), 1 << 20));
        r.opened(CONN, 1_000);
        r.wire(CONN, Direction.SERVER_TO_CLIENT, new WireEvent.Unframed(0, new byte[100], "first"), 2_000);
        r.flush();
        assertTrue(ch.forcing.await(20, TimeUnit.SECONDS), "the flush had the file forced");
        long before = ch.size();
        // the force hangs: what comes next is still written to the file, and the caller never waits for it
        for (int i = 0; i < 50; i++) {
            r.wire(CONN, Direction.SERVER_TO_CLIENT, new WireEvent.Unframed(100 + 100L * i, new byte[100], "more"), 3_000 + i);
        }
        r.flush();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (ch.size() == before && System.nanoTime() < deadline) {
            Thread.onSpinWait();
        }
        assertTrue(ch.size() > before, "the second chunk reached the file while the first force hung");
        assertEquals(1, ch.release.getCount(), "the force was still hanging meanwhile");
        assertEquals(Set.of("spy-log-sync"), ch.forcers, "forced beside the log thread, not on it");
        ch.release.countDown();
        r.closed(CONN, 10_000, "done");
        r.close();
        try (SpyLogReader in = SpyLogReader.open(log)) {
            assertEquals(51, in.messageCount(), "every wire entry is in the log");
            assertEquals(2, in.eventCount(), "and the open and close events");
        }
    }

    @Test
    void writesEveryCallInOrderOnItsOwnThread() throws Exception {
        Path log = dir.resolve("order.mcap");
        WatchedChannel ch = new WatchedChannel(log);
        String caller = Thread.currentThread().getName();
        ch.writers.clear();
        LogRecorder r = new LogRecorder(SpyLogWriter.create(ch, Map.of(), 4096));
        ch.writers.clear(); // the header is written by the caller, at creation
        Random random = new Random(17);
        ByteArrayOutputStream[] sent = { new ByteArrayOutputStream(), new ByteArrayOutputStream() };
        r.opened(CONN, 1_000);
        for (int i = 0; i < 5_000; i++) {
            Direction d = Direction.values()[random.nextInt(2)];
            byte[] piece = new byte[1 + random.nextInt(300)];
            random.nextBytes(piece);
            ByteArrayOutputStream s = sent[d.ordinal()];
            r.wire(CONN, d, new WireEvent.Unframed(s.size(), piece, "test"), 2_000 + i);
            s.write(piece);
            if (i % 1000 == 0) {
                r.flush();
            }
        }
        r.closed(CONN, 10_000, "done");
        r.close();

        assertTrue(ch.writers.contains("spy-log"), ch.writers.toString());
        assertTrue(!ch.writers.contains(caller), "the caller does not write the file: " + ch.writers);
        try (SpyLogReader in = SpyLogReader.open(log)) {
            for (Direction d : Direction.values()) {
                assertArrayEquals(sent[d.ordinal()].toByteArray(), in.streamBytes(1, d), d + " in stream order");
            }
            assertEquals(5_000, in.messageCount());
        }
    }

    @Test
    void aFullDiskStopsTheLogAndSaysWhy() throws Exception {
        Path log = dir.resolve("full.mcap");
        WatchedChannel ch = new WatchedChannel(log);
        LogRecorder r = new LogRecorder(SpyLogWriter.create(ch, Map.of(), 4096));
        ch.failAfter = ch.written + 20_000;
        r.opened(CONN, 1);
        IOException thrown = null;
        byte[] piece = new byte[1000];
        for (int i = 0; i < 1_000_000 && thrown == null; i++) {
            try {
                r.wire(CONN, Direction.SERVER_TO_CLIENT, new WireEvent.Unframed(i * 1000L, piece, "x"), i);
                if (i % 100 == 0) {
                    r.flush();
                }
            } catch (IOException e) {
                thrown = e;
            }
        }
        assertTrue(thrown != null && thrown.getMessage().contains("No space left on device"), String.valueOf(thrown));
        IOException atClose = assertThrows(IOException.class, r::close);
        assertTrue(atClose.getMessage().contains("No space left on device"), atClose.getMessage());
        try (SpyLogReader in = SpyLogReader.open(log)) {
            assertTrue(in.messageCount() > 0, "the complete chunks before the failure are kept");
        }
    }

    @Test
    void theCallerWaitsWhenTheLogFallsBehindSoMemoryStaysBounded() throws Exception {
        Path log = dir.resolve("slow.mcap");
        WatchedChannel ch = new WatchedChannel(log);
        LogRecorder r = new LogRecorder(SpyLogWriter.create(ch, Map.of(), 1 << 20));
        CountDownLatch gate = new CountDownLatch(1);
        ch.gate = gate; // the disk stalls
        int pieceSize = 64 << 10;
        int pieces = (int) (4 * LogRecorder.MAX_QUEUED_BYTES / pieceSize);
        AtomicInteger handed = new AtomicInteger();
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread producer = Thread.ofPlatform().name("observation-stand-in").start(() -> {
            try {
                r.opened(CONN, 1);
                for (int i = 0; i < pieces; i++) {
                    r.wire(CONN, Direction.SERVER_TO_CLIENT,
                            new WireEvent.Unframed((long) i * pieceSize, new byte[pieceSize], "x"), 2 + i);
                    handed.incrementAndGet();
                }
                r.close();
            } catch (Throwable t) {
                failed.set(t);
            }
        });
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (producer.getState() != Thread.State.WAITING && System.nanoTime() < deadline) {
            Thread.onSpinWait();
        }
        assertEquals(Thread.State.WAITING, producer.getState(), "the caller waits for the stalled log");
        long held = (long) handed.get() * pieceSize;
        // the hand-over budget, the caller's open batch, and the writer's open chunk (1 MiB)
        assertTrue(held <= LogRecorder.MAX_QUEUED_BYTES + 2L * LogRecorder.BATCH_BYTES + (1 << 20) + 2L * pieceSize,
                "at most the hand-over budget is held: " + held);
        gate.countDown();
        producer.join(TimeUnit.SECONDS.toMillis(30));
        assertEquals(null, failed.get());
        assertEquals(pieces, handed.get());
        try (SpyLogReader in = SpyLogReader.open(log)) {
            assertEquals((long) pieces * pieceSize, in.streamBytes(1, Direction.SERVER_TO_CLIENT).length);
        }
    }
}
