package org.stagecraft.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.replay.export.CsvExport;
import org.stagecraft.replay.export.ExportFilter;
import org.stagecraft.replay.export.McapExport;
import org.stagecraft.replay.export.WritelogExport;
import org.stagecraft.replay.log.LogProblem;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.writelog.WritelogWriter;
import org.stagecraft.streams.StreamPattern;

/**
 * {@code stagecraft export FILE --format csv|writelog|mcap [--from S] [--until S] [--stream PATTERN]
 * [--grep TEXT] [--out FILE]}: a log, or part of it, in another format. Text formats go to standard
 * output without {@code --out}; MCAP needs a file.
 */
final class ExportCommand {
    static final String USAGE = "usage: stagecraft export FILE --format csv|writelog|mcap [--from SECONDS] [--until SECONDS]"
            + " [--stream PATTERN] [--grep TEXT] [--out FILE]";

    int run(String[] args, PrintStream out, PrintStream err) {
        String file = null;
        String format = null;
        Double from = null;
        Double until = null;
        String stream = null;
        String grep = null;
        String outFile = null;
        CodecRegistry registry = CodecRegistry.standard();
        try {
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "--format" -> format = value(args, ++i, a);
                    case "--from" -> from = seconds(value(args, ++i, a), a);
                    case "--until" -> until = seconds(value(args, ++i, a), a);
                    case "--stream" -> stream = value(args, ++i, a);
                    case "--grep" -> grep = value(args, ++i, a);
                    case "--out" -> outFile = value(args, ++i, a);
                    default -> {
                        if (a.startsWith("--") || file != null) {
                            throw new IllegalArgumentException("unexpected argument '" + a + "'");
                        }
                        file = a;
                    }
                }
            }
            if (file == null || format == null) {
                throw new IllegalArgumentException(file == null ? "no FILE given" : "no --format given");
            }
            if (!format.equals("csv") && !format.equals("writelog") && !format.equals("mcap")) {
                throw new IllegalArgumentException("--format must be csv, writelog or mcap, not '" + format + "'");
            }
            if (format.equals("mcap") && outFile == null) {
                throw new IllegalArgumentException("--format mcap needs --out FILE (MCAP is binary)");
            }
            if (from != null && until != null && until < from) {
                throw new IllegalArgumentException("--until " + until + " is before --from " + from);
            }
        } catch (IllegalArgumentException e) {
            err.println("stagecraft export: " + e.getMessage());
            err.println(USAGE);
            return ExitCode.USAGE;
        }
        StreamPattern pattern;
        try {
            pattern = stream == null ? null : ExportFilter.parsePattern(stream, registry);
        } catch (IllegalArgumentException e) {
            err.println("stagecraft export: --stream: " + e.getMessage());
            return ExitCode.USAGE;
        }
        ExportFilter filter = new ExportFilter(from, until, pattern, grep);
        Path input = InputFile.readable("export", file, err);
        if (input == null) {
            return ExitCode.FAILED;
        }
        try (SessionLog log = SessionLogs.open(input)) {
            if (log.messageCount() == 0 && log.problems().stream().anyMatch(LogProblem::dataLost)) {
                // a file nothing could be read from gets no empty output file
                LogLosses.print("export", log, err);
                err.println("stagecraft export: " + input + ": nothing could be read; nothing written");
                return ExitCode.FAILED;
            }
            switch (format) {
                case "mcap" -> {
                    McapExport.Summary s = McapExport.write(log, filter, registry, Path.of(outFile));
                    err.println("stagecraft export: wrote " + outFile + ": " + s.robots().size()
                            + (s.robots().size() == 1 ? " robot " : " robots ") + s.robots() + " on " + s.foxgloveChannels() + " Foxglove channels, " + s.jsonMessages()
                            + " Player messages on " + s.jsonChannels() + " JSON channels, " + s.wireEntries()
                            + " wire entries");
                }
                case "csv" -> {
                    try (Writer w = writer(outFile, out)) {
                        long rows = CsvExport.write(log, filter, registry, w);
                        err.println("stagecraft export: " + rows + " rows" + (outFile != null ? " to " + outFile : ""));
                    }
                }
                default -> {
                    try (Writer w = writer(outFile, out)) {
                        WritelogWriter.Summary s = WritelogExport.write(log, filter, registry, w);
                        err.println("stagecraft export: " + s.written() + " lines" + (outFile != null ? " to " + outFile : "")
                                + (s.approximated() > 0 ? ", " + s.approximated() + " of them with less than they hold"
                                        + " (writelog keeps only part of some geometry)" : "")
                                + (s.duplicates() > 0 ? ", " + s.duplicates() + " repeats of a message already written left out" : ""));
                        for (Map.Entry<String, Long> e : s.skipped().entrySet()) {
                            err.println("  skipped " + e.getValue() + " x " + e.getKey());
                        }
                    }
                }
            }
            // damage inside a log is found as its chunks are read: what the export could not read is known now
            return LogLosses.report("export", log, err);
        } catch (NoSuchFileException e) {
            err.println("stagecraft export: " + e.getFile() + ": cannot be written or read (no such file or directory)");
            return ExitCode.FAILED;
        } catch (IOException e) {
            err.println("stagecraft export: " + e.getMessage());
            return ExitCode.FAILED;
        } catch (RuntimeException | OutOfMemoryError e) {
            err.println("stagecraft export: " + CommandFailure.describe(input, e));
            return ExitCode.FAILED;
        }
    }

    /** Standard output stays open after the export; a file is closed. */
    private static Writer writer(@Nullable String outFile, PrintStream out) throws IOException {
        if (outFile != null) {
            return Files.newBufferedWriter(Path.of(outFile), StandardCharsets.UTF_8);
        }
        return new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16) {
            @Override
            public void close() throws IOException {
                flush();
            }
        };
    }

    private static String value(String[] args, int i, String option) {
        if (i >= args.length) {
            throw new IllegalArgumentException(option + " needs a value");
        }
        return args[i];
    }

    private static double seconds(String text, String option) {
        try {
            double v = Double.parseDouble(text);
            if (!(v >= 0) || Double.isInfinite(v)) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " needs seconds from the log's start (a number >= 0), not '" + text + "'");
        }
    }
}
