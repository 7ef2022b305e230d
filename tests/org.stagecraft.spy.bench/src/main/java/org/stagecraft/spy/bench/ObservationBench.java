package org.stagecraft.spy.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.recording.peers.RecordedConnection;
import org.stagecraft.spy.log.SpyLogWriter;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.LogRecorder;
import org.stagecraft.spy.proxy.ObservationPipeline;
import org.stagecraft.streams.DeliveryPolicy;
import org.stagecraft.streams.StreamBus;
import org.stagecraft.streams.StreamPattern;

/**
 * How fast the spy's observation side (framing, decoding, publishing, logging) runs on its own,
 * without sockets: the recorded sessions are handed to the pipeline as the relay would hand them,
 * and the clock stops when it has drained. This is the rate above which a saturated spy starts
 * skipping (and counting) bytes it forwarded.
 *
 * <pre>java -cp spy-bench.jar org.stagecraft.spy.bench.ObservationBench [repeat]</pre>
 */
public final class ObservationBench {
    private ObservationBench() {
    }

    public static void main(String[] args) throws Exception {
        int repeat = args.length > 0 ? Integer.parseInt(args[0]) : 4;
        Workload w = Workload.load(6, repeat);
        for (int round = 0; round < 3; round++) {
            for (boolean log : new boolean[] {false, true}) {
                run(w, log);
            }
        }
    }

    private static long processCpu() {
        return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    private static long threadCpu(ThreadMXBean threads, String name) {
        for (ThreadInfo t : threads.getThreadInfo(threads.getAllThreadIds())) {
            if (t != null && t.getThreadName().equals(name)) {
                return threads.getThreadCpuTime(t.getThreadId());
            }
        }
        return -1;
    }

    private static void run(Workload w, boolean log) throws Exception {
        Path file = log ? Files.createTempFile("observation-bench", ".mcap") : null;
        try (StreamBus bus = new StreamBus()) {
            bus.subscribe(StreamPattern.any(), DeliveryPolicy.latestValue(), m -> { });
            bus.subscribe(StreamPattern.any(), DeliveryPolicy.lossless(1 << 16), m -> { });
            ObservationPipeline pipeline = new ObservationPipeline(bus, new PlayerDecoder(CodecRegistry.standard()),
                    log ? new LogRecorder(SpyLogWriter.create(file, Map.of())) : null, Long.MAX_VALUE);
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            long cpu0 = processCpu();
            long main0 = threads.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            int id = 1;
            for (RecordedConnection s : w.sessions()) {
                ConnectionInfo c = new ConnectionInfo(id++, 6665, "127.0.0.1:" + (40000 + id), "127.0.0.1:6665", "127.0.0.1:7665");
                pipeline.opened(c, System.nanoTime());
                for (byte[] chunk : s.serverChunks()) {
                    pipeline.chunk(c, Direction.SERVER_TO_CLIENT, chunk, System.nanoTime());
                }
                for (byte[] chunk : s.clientChunks()) {
                    pipeline.chunk(c, Direction.CLIENT_TO_SERVER, chunk, System.nanoTime());
                }
                pipeline.closed(c, System.nanoTime(), "done");
            }
            long feeding = threads.getCurrentThreadCpuTime() - main0;
            // the observation thread's CPU time once it has published everything (it ends at close)
            while (pipeline.heldBytes() > 0) { // every connection is closed: all its events are queued
                Thread.onSpinWait();
            }
            long observer = threadCpu(threads, "spy-observer");
            pipeline.close();
            double s = (System.nanoTime() - t0) / 1e9;
            long n = pipeline.messages();
            System.out.printf("observation %-14s %8.1f MB/s %10.0f messages/s (%d messages, %d dropped bytes);"
                    + " CPU ns/message: framing+decoding %.0f, observation thread %.0f, whole process %.0f%n",
                    log ? "decode+bus+log" : "decode+bus", w.bytes() / 1e6 / s, n / s, n, pipeline.droppedBytes(),
                    (double) feeding / n, (double) observer / n, (double) (processCpu() - cpu0) / n);
        } finally {
            if (file != null) {
                Files.deleteIfExists(file);
            }
        }
    }
}
