package org.stagecraft.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.recording.fuzz.FramingCheck;
import org.stagecraft.recording.fuzz.TraceMutator;
import org.stagecraft.recording.trace.TraceCorpus;

/**
 * The long fuzz run of the decode path ({@code ./stagecraft bench fuzz}): mutated variants of the
 * recorded traffic, bigger than the test suite's, for as long as asked, each through the trace reader,
 * the framers, the decoder ({@link FramingCheck}: every byte accounted for, the session framer agreeing
 * with one plain framer per stream) and {@code stagecraft decode} (one JSON line per event, and the exit
 * code and message {@link ExpectedDecode} says). A variant that breaks any of it is saved with its
 * description under {@code fuzz-failures/} and counted; the run goes on. Prints progress and figures;
 * exits 1 if anything failed. Lives with the tests of the command line tool (and is compiled with them)
 * because it runs the tool's own {@code decode}; not a test itself: the suite runs the short fuzz,
 * {@link RecordedTrafficFuzzTest}.
 *
 * <pre>
 * ./stagecraft bench fuzz [--seconds 600] [--seed N] [--max-records 2000]
 * </pre>
 */
public final class FuzzSoak {
    private FuzzSoak() {
    }

    public static void main(String[] args) throws IOException {
        long seconds = 600;
        long seed = System.nanoTime();
        int maxRecords = 2000;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--seconds" -> seconds = Long.parseLong(args[++i]);
                case "--seed" -> seed = Long.decode(args[++i]);
                case "--max-records" -> maxRecords = Integer.parseInt(args[++i]);
                default -> {
                    System.err.println("usage: FuzzSoak [--seconds 600] [--seed N] [--max-records 2000]");
                    System.exit(2);
                }
            }
        }
        Path work = Files.createTempDirectory("stagecraft-fuzz");
        Path file = work.resolve("variant.trace.jsonl");
        Path failures = Path.of("fuzz-failures");
        TraceMutator mutator = new TraceMutator(TraceCorpus.all(), seed);
        FramingCheck check = new FramingCheck(new PlayerDecoder(CodecRegistry.standard()));
        System.out.printf("fuzzing the decode path for %d s, seed %#x, windows of up to %d records, max heap %d MiB%n", seconds, seed,
                maxRecords, Runtime.getRuntime().maxMemory() >> 20);

        long variants = 0, text = 0, streamBytes = 0, messages = 0, unframed = 0, problems = 0, refused = 0, jsonLines = 0;
        List<String> broken = new ArrayList<>();
        long start = System.nanoTime();
        long end = start + seconds * 1_000_000_000L;
        long nextReport = start + 30_000_000_000L;
        long firstLive = -1, lastLive = 0, maxLive = 0;
        while (System.nanoTime() < end) {
            TraceMutator.Variant v = mutator.next(maxRecords);
            variants++;
            text += v.file().length;
            Files.write(file, v.file());
            String problem;
            try {
                FramingCheck.Outcome o = check.check(file.toString(), v.file());
                LineCounter out = new LineCounter();
                java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
                int code = Main.run(new String[] { "decode", file.toString() }, new PrintStream(out, false, StandardCharsets.UTF_8),
                        new PrintStream(err, true, StandardCharsets.UTF_8));
                String errText = err.toString(StandardCharsets.UTF_8);
                ExpectedDecode expected = ExpectedDecode.of(o);
                if (code != expected.code() || !errText.equals(expected.err())) {
                    problem = "decode exited " + code + " with '" + errText.strip() + "'; expected " + expected.code() + " with '"
                            + expected.err().strip() + "'";
                } else if (out.lines != o.events()) {
                    problem = "decode printed " + out.lines + " lines for " + o.events() + " events";
                } else {
                    problem = null;
                }
                streamBytes += o.chunkBytes();
                messages += o.frames();
                unframed += o.unframedBytes();
                problems += o.decodeProblems();
                refused += o.refusal() == null ? 0 : 1;
                jsonLines += out.lines;
            } catch (RuntimeException | StackOverflowError | OutOfMemoryError e) {
                problem = e.toString();
            }
            if (problem != null) {
                Files.createDirectories(failures);
                Path saved = failures.resolve("variant-" + v.number() + ".trace.jsonl");
                Files.write(saved, v.file());
                Files.writeString(failures.resolve("variant-" + v.number() + ".txt"), v.description() + "\n" + problem + "\n");
                broken.add("variant " + v.number() + " (" + v.description() + "): " + problem + " -> " + saved);
                System.out.println("FAILED " + broken.getLast());
            }
            if (variants % 100 == 1) { // the live heap must stay flat however many variants went through
                lastLive = liveHeap();
                firstLive = firstLive < 0 ? lastLive : firstLive;
                maxLive = Math.max(maxLive, lastLive);
            }
            long now = System.nanoTime();
            if (now >= nextReport) {
                nextReport += 30_000_000_000L;
                System.out.printf("  %4.0f s: %d variants, %.0f MB of trace text, %d failed%n", (now - start) / 1e9, variants, text / 1e6,
                        broken.size());
            }
        }
        double took = (System.nanoTime() - start) / 1e9;
        System.out.printf("%nfuzz soak: %d variants in %.0f s (seed %#x)%n", variants, took, seed);
        System.out.printf("  input:    %.1f MB of trace text (%.1f MB/s), %.1f MB of stream bytes%n", text / 1e6, text / 1e6 / took,
                streamBytes / 1e6);
        System.out.printf("  framed:   %d messages, %d unframed bytes, %d decode problems, %d JSON lines from decode%n", messages,
                unframed, problems, jsonLines);
        System.out.printf("  refused:  %d files (file, line and reason; exit 1, or 3 after what came before the bad line)%n", refused);
        System.out.printf("  failures: %d (unchecked exceptions, bytes not accounted for, framers disagreeing, wrong exit)%n",
                broken.size());
        System.out.printf("  memory:   live heap after a full GC every 100 variants: first %.1f MiB, last %.1f MiB, at most %.1f MiB"
                + " (maximum heap %d MiB)%n", firstLive / 1048576.0, lastLive / 1048576.0, maxLive / 1048576.0,
                Runtime.getRuntime().maxMemory() >> 20);
        try (var files = Files.list(work)) {
            for (Path p : files.toList()) {
                Files.deleteIfExists(p);
            }
        }
        Files.deleteIfExists(work);
        System.exit(broken.isEmpty() ? 0 : 1);
    }

    /** Heap in use after a full collection: what is still referenced (a benchmark may ask for one). */
    private static long liveHeap() {
        System.gc();
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }

    /** Counts the lines decode prints, keeping none of them. */
    private static final class LineCounter extends OutputStream {
        long lines;

        @Override
        public void write(int b) {
            if (b == '\n') {
                lines++;
            }
        }

        @Override
        public void write(byte[] b, int off, int len) {
            for (int i = off; i < off + len; i++) {
                if (b[i] == '\n') {
                    lines++;
                }
            }
        }
    }
}
