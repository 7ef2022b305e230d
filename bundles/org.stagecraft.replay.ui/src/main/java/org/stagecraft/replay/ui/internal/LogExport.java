package org.stagecraft.replay.ui.internal;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.replay.export.CsvExport;
import org.stagecraft.replay.export.ExportFilter;
import org.stagecraft.replay.export.McapExport;
import org.stagecraft.replay.export.WritelogExport;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.replay.log.SessionLogs;
import org.stagecraft.replay.writelog.WritelogWriter;

/**
 * Runs an export of a log file in the background (a Job: the editor and the replay go on), through
 * org.stagecraft.replay.export, and says what was written in the job's result. The job opens the file
 * itself and closes it when done: the editor's own log may be replaced at any moment (a reload, a
 * growing file followed) and must not be closed under the export. An export that fails leaves no
 * partial file behind and says what went wrong.
 */
public final class LogExport {
    /** The three exports the editor offers. */
    public enum Kind {
        CSV("CSV"), WRITELOG("Player writelog"), MCAP("MCAP with JSON channels");

        final String title;

        Kind(String title) {
            this.title = title;
        }
    }

    private static final String BUNDLE = "org.stagecraft.replay.ui";

    private LogExport() {
    }

    /**
     * A scheduled job writing the log in {@code file} (what {@code filter} takes) as {@code kind} to {@code out},
     * decoding with {@code registry} (the workbench's: contributed decoders included).
     */
    public static Job start(Path file, Kind kind, ExportFilter filter, CodecRegistry registry, Path out) {
        Job job = Job.create("Export " + file.getFileName() + " to " + out.getFileName(), monitor -> {
            SessionLog log;
            try {
                log = SessionLogs.open(file, registry); // decoded as the editor shows it
            } catch (IOException | RuntimeException e) {
                return failed(kind, file, out, e, ""); // nothing written: a file already at out stays
            }
            try (log) {
                String what = write(log, kind, filter, registry, out);
                return new Status(IStatus.OK, BUNDLE, kind.title + ": " + what + " written to " + out);
            } catch (IOException | RuntimeException e) {
                return failed(kind, file, out, e, deletePartial(out));
            }
        });
        job.setUser(true);
        job.schedule();
        return job;
    }

    private static IStatus failed(Kind kind, Path file, Path out, Exception e, String left) {
        return new Status(IStatus.ERROR, BUNDLE, kind.title + " export of " + file + " to " + out + " failed: " + describe(e) + left, e);
    }

    /** The exception's class and message: some (ClosedChannelException) have no message at all. */
    public static String describe(Throwable e) {
        String m = e.getMessage();
        return e.getClass().getSimpleName() + (m == null || m.isBlank() ? "" : ": " + m);
    }

    /** Removes what a failed export wrote; says so when even that fails. */
    private static String deletePartial(Path out) {
        try {
            Files.deleteIfExists(out);
            return "";
        } catch (IOException e) {
            return " (the partial file could not be removed: " + describe(e) + ")";
        }
    }

    static String write(SessionLog log, Kind kind, ExportFilter filter, CodecRegistry registry, Path out) throws IOException {
        return switch (kind) {
            case CSV -> {
                try (Writer w = Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
                    yield String.format(Locale.ROOT, "%,d rows", CsvExport.write(log, filter, registry, w));
                }
            }
            case WRITELOG -> {
                try (Writer w = Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
                    WritelogWriter.Summary s = WritelogExport.write(log, filter, registry, w);
                    yield String.format(Locale.ROOT, "%,d messages (%,d approximated, %,d with no writelog form)", s.written(),
                            s.approximated(), s.skippedTotal());
                }
            }
            case MCAP -> {
                Files.deleteIfExists(out);
                McapExport.Summary s = McapExport.write(log, filter, registry, out);
                yield String.format(Locale.ROOT,
                        "%d %s on %d Foxglove channels, %,d Player messages on %d JSON channels, %,d wire entries",
                        s.robots().size(), s.robots().size() == 1 ? "robot" : "robots", s.foxgloveChannels(), s.jsonMessages(), s.jsonChannels(), s.wireEntries());
            }
        };
    }
}
