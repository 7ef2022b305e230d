package org.stagecraft.replay.log;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.recording.trace.TraceReader;
import org.stagecraft.replay.writelog.WritelogImport;
import org.stagecraft.spy.log.SpyLogReader;
import org.stagecraft.spy.log.SpyLogWriter;

/**
 * Opens any log a user can give: a spy log, a recorded trace or a Player writelog file, recognised
 * by content rather than by name. A spy log is read in place through its index. A trace or writelog
 * file is first written into a temporary spy log (deleted on close), so every log is replayed,
 * sought and inspected by the same code, with memory flat in the log's size.
 */
public final class SessionLogs {
    /** How much of a file tells its format. */
    public static final int HEAD = 512;

    private SessionLogs() {
    }

    /**
     * Opens {@code file}, decoding with Player's standard interfaces. A truncated or partly corrupt
     * file opens with what is readable and says where it stopped in {@link SessionLog#problems()}.
     *
     * @throws IOException naming the file when it cannot be read or is none of the known formats
     */
    public static SessionLog open(Path file) throws IOException {
        return open(file, CodecRegistry.standard());
    }

    /** As {@link #open(Path)}, decoding with {@code codecs} (e.g. with interfaces plug-ins add). */
    public static SessionLog open(Path file, CodecRegistry codecs) throws IOException {
        LogFormat format = formatOf(file);
        return switch (format) {
            case SPY_LOG -> new SpyLogSession(file, format, SpyLogReader.open(file), codecs, List.of(), () -> {
            });
            case PLAYER_TRACE -> imported(file, format, codecs, TraceImport.metadata(file),
                    out -> TraceImport.convert(file, out));
            case WRITELOG -> imported(file, format, codecs, Map.of("imported-from", file.toString(), "format", "writelog"),
                    out -> WritelogImport.convert(file, out));
        };
    }

    /**
     * What {@code file} holds, told by its first bytes; when they tell nothing, by what its name
     * promises: a {@code .mcap} file that is not MCAP is refused as such, and a {@code .jsonl} file is
     * taken for a player-trace, whose reader then says on which line and why it is not one.
     *
     * @throws IOException naming the file once and what it is not
     */
    public static LogFormat formatOf(Path file) throws IOException {
        byte[] head = head(file);
        Optional<LogFormat> format = formatOf(head);
        if (format.isPresent()) {
            return format.get();
        }
        String name = String.valueOf(file.getFileName()).toLowerCase(Locale.ROOT);
        if (name.endsWith(".mcap")) {
            throw new IOException(notMcap(file, head));
        }
        if (name.endsWith(".jsonl")) {
            return LogFormat.PLAYER_TRACE;
        }
        throw new IOException(file + ": not a log Stagecraft can open (expected an MCAP"
                + " spy log, a player-trace .trace.jsonl file or a Player writelog file)");
    }

    /** The first {@value #HEAD} bytes of {@code file} (all of a shorter one). */
    public static byte[] head(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file)) {
            return in.readNBytes(HEAD);
        } catch (NoSuchFileException e) {
            throw new NoSuchFileException(file.toString(), null, "no such file");
        }
    }

    /** E.g. "x.mcap: not an MCAP file: it is empty (0 bytes)": for a file whose name promises MCAP. */
    public static String notMcap(Path file, byte[] head) {
        return file + ": not an MCAP file: " + Objects.requireNonNullElse(SpyLogReader.whyNotMcap(head), "it is one");
    }

    /**
     * What a file starting with {@code head} holds (its first {@value #HEAD} bytes, or all of a shorter
     * file), or empty when it is none of the known formats. The one rule for both opening a file and
     * recognising it (the IDE's content types ask this too), so whatever is offered can be opened.
     */
    public static Optional<LogFormat> formatOf(byte[] head) {
        if (SpyLogReader.isMcap(head)) {
            return Optional.of(LogFormat.SPY_LOG);
        }
        String text = new String(head, StandardCharsets.UTF_8);
        if (text.startsWith("{") && text.contains("\"format\"") && text.contains("\"" + TraceReader.FORMAT + "\"")) {
            return Optional.of(LogFormat.PLAYER_TRACE);
        }
        if (WritelogImport.looksLikeWritelog(head)) {
            return Optional.of(LogFormat.WRITELOG);
        }
        return Optional.empty();
    }

    private interface Import {
        List<LogProblem> into(SpyLogWriter out) throws IOException;
    }

    private static SessionLog imported(Path file, LogFormat format, CodecRegistry codecs, Map<String, String> metadata,
            Import importer) throws IOException {
        Path tmp = Files.createTempFile("stagecraft-import-", ".mcap");
        Runnable delete = () -> {
            try {
                Files.deleteIfExists(tmp);
            } catch (IOException e) {
                tmp.toFile().deleteOnExit();
            }
        };
        try {
            List<LogProblem> problems;
            try (SpyLogWriter out = SpyLogWriter.create(tmp, metadata)) {
                problems = importer.into(out);
            }
            return new SpyLogSession(file, format, SpyLogReader.open(tmp), codecs, problems, delete);
        } catch (IOException | RuntimeException e) {
            delete.run();
            throw e;
        }
    }
}
