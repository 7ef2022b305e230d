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
import org.stagecraft.replay.writelog.WritelogWriter;

/**
 * Runs an export of an open log in the background (a Job: the editor and the replay go on), through
 * org.stagecraft.replay.export, and says what was written in the job's result.
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

    /** A scheduled job writing {@code log} (what {@code filter} takes) as {@code kind} to {@code out}. */
    public static Job start(SessionLog log, Kind kind, ExportFilter filter, CodecRegistry registry, Path out) {
        Job job = Job.create("Export " + log.path().getFileName() + " to " + out.getFileName(), monitor -> {
            try {
                String what = write(log, kind, filter, registry, out);
                return new Status(IStatus.OK, BUNDLE, kind.title + ": " + what + " written to " + out);
            } catch (IOException | RuntimeException e) {
                return new Status(IStatus.ERROR, BUNDLE, kind.title + " export to " + out + " failed: " + e.getMessage(), e);
            }
        });
        job.setUser(true);
        job.schedule();
        return job;
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
                yield String.format(Locale.ROOT, "%,d JSON messages on %d channels, %,d wire entries", s.jsonMessages(),
                        s.jsonChannels(), s.wireEntries());
            }
        };
    }
}
