package org.stagecraft.player.bench;

import java.nio.file.Path;

import org.openjdk.jmh.results.RunResult;
import org.stagecraft.player.wire.PlayerFramer;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.options.Options;
import org.openjdk.jmh.runner.options.OptionsBuilder;

/**
 * Runs {@link CodecBenchmark} and reports throughput in MB/s and messages/s on one core.
 * Usage: java -Dstagecraft.traces=DIR -jar benchmarks.jar
 */
public final class BenchMain {
    private BenchMain() {
    }

    public static void main(String[] args) throws Exception {
        String traces = System.getProperty("stagecraft.traces", "tests/traces");
        RecordedTraffic corpus = RecordedTraffic.load(Path.of(traces));
        long messages = 0;
        for (RecordedTraffic.Stream_ s : corpus.streams) {
            PlayerFramer framer = new PlayerFramer(s.id().dir(), e -> { });
            s.chunks().forEach(framer::accept);
            framer.end();
            messages += framer.framedMessages();
        }
        Options opts = new OptionsBuilder().include(CodecBenchmark.class.getSimpleName())
                .jvmArgsAppend("-Dstagecraft.traces=" + traces).build();
        System.out.printf("corpus: %d streams, %.2f MB, %d messages%n", corpus.streams.size(), corpus.bytes / 1e6,
                messages);
        for (RunResult r : new Runner(opts).run()) {
            double ms = r.getPrimaryResult().getScore();
            double err = r.getPrimaryResult().getScoreError();
            String name = r.getParams().getBenchmark().replaceAll(".*\\.", "");
            System.out.printf("%-16s %8.3f ms/corpus (±%.3f)  %8.1f MB/s  %10.0f messages/s%n", name, ms, err,
                    corpus.bytes / 1e6 / (ms / 1e3), messages / (ms / 1e3));
        }
    }
}
