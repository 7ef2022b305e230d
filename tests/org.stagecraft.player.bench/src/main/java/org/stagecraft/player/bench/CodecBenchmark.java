package org.stagecraft.player.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.PlayerFramer;
import org.stagecraft.player.wire.WireEvent;

/**
 * Framing (and framing + decoding) of all recorded Player/Stage traffic on one thread. One
 * operation = the whole corpus, fed in the chunks the recorder saw; {@link BenchMain} turns the
 * score into MB/s and messages/s.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 5, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = {"-Xmx1g"})
public class CodecBenchmark {

    private RecordedTraffic traffic;
    private PlayerDecoder decoder;

    @Setup(Level.Trial)
    public void load() throws IOException {
        traffic = RecordedTraffic.load(Path.of(System.getProperty("stagecraft.traces", "tests/traces")));
        decoder = new PlayerDecoder(CodecRegistry.standard());
    }

    @Benchmark
    public long frame(Blackhole bh) {
        long messages = 0;
        for (RecordedTraffic.Stream_ s : traffic.streams) {
            PlayerFramer framer = new PlayerFramer(s.id().dir(), bh::consume);
            for (byte[] chunk : s.chunks()) {
                framer.accept(chunk);
            }
            framer.end();
            messages += framer.framedMessages();
        }
        return messages;
    }

    @Benchmark
    public long frameAndDecode(Blackhole bh) {
        long[] messages = {0};
        for (RecordedTraffic.Stream_ s : traffic.streams) {
            PlayerFramer framer = new PlayerFramer(s.id().dir(), e -> {
                if (e instanceof WireEvent.Frame f) {
                    bh.consume(decoder.decode(f));
                    messages[0]++;
                }
            });
            for (byte[] chunk : s.chunks()) {
                framer.accept(chunk);
            }
            framer.end();
        }
        return messages[0];
    }
}
