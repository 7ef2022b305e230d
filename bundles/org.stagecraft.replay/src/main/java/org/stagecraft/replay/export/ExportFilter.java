package org.stagecraft.replay.export;

import java.io.IOException;
import java.util.Locale;
import java.util.Map;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.replay.fields.FlatFields;
import org.stagecraft.replay.log.HeaderNames;
import org.stagecraft.replay.log.LogCursor;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.replay.log.SessionLog;
import org.stagecraft.streams.StreamPattern;

/**
 * Which Player messages of a log an export takes: a time range (seconds from the log's start), a
 * stream pattern (the stream bus's text syntax, where {@code dev} and {@code type} may also be
 * names: {@code dev=laser type=DATA}) and free text that must occur, ignoring case, in the message's
 * description (interface, index, type and subtype names, addresses, and {@code field=value} for
 * every field).
 *
 * @param fromSeconds  start of the range from the log's start, or null for the start
 * @param untilSeconds end of the range (inclusive), or null for the end
 * @param pattern      the streams to take, or null for all
 * @param grep         text to look for, or null
 */
public record ExportFilter(@Nullable Double fromSeconds, @Nullable Double untilSeconds, @Nullable StreamPattern pattern, @Nullable String grep) {

    public static ExportFilter all() {
        return new ExportFilter(null, null, null, null);
    }

    public boolean isAll() {
        return fromSeconds == null && untilSeconds == null && pattern == null && (grep == null || grep.isEmpty());
    }

    /** Receives the log messages an export takes, in log order. */
    interface MessageAction {
        void accept(LogMessage m) throws IOException;
    }

    /**
     * Calls {@code action} for every entry of {@code log} in the time range, in log order, reading
     * from the range's start and stopping after its end. The stream and text parts are the caller's
     * ({@link #takes}), since some exports keep entries the filter does not describe.
     */
    void forEachInRange(SessionLog log, MessageAction action) throws IOException {
        long start = log.startNanos();
        long from = fromSeconds == null ? Long.MIN_VALUE : start + Math.round(fromSeconds * 1e9);
        try (LogCursor c = log.cursor(from)) {
            for (LogMessage m = c.next(); m != null; m = c.next()) {
                if (inTime(m.timeNanos(), start)) {
                    action.accept(m);
                } else if (untilSeconds != null && (m.timeNanos() - start) / 1e9 > untilSeconds) {
                    break;
                }
            }
        }
    }

    /** Whether a log entry's time lies in the range; {@code startNanos} is the log's start. */
    public boolean inTime(long timeNanos, long startNanos) {
        double t = (timeNanos - startNanos) / 1e9;
        return (fromSeconds == null || t >= fromSeconds) && (untilSeconds == null || t <= untilSeconds);
    }

    /** Whether a Player message (a frame) passes the stream pattern and the text. */
    public boolean takes(LogMessage m, CodecRegistry registry) {
        if (m.kind() != LogMessage.Kind.FRAME || m.decoded() == null) {
            return false;
        }
        if (pattern != null) {
            var key = m.toStreamMessage().map(s -> s.key());
            if (key.isEmpty() || !pattern.matches(key.get())) {
                return false;
            }
        }
        return grep == null || grep.isEmpty()
                || describe(m, registry).toLowerCase(Locale.ROOT).contains(grep.toLowerCase(Locale.ROOT));
    }

    /** The text {@link #grep} searches. */
    static String describe(LogMessage m, CodecRegistry registry) {
        MessageHeader h = m.decoded().header();
        StringBuilder b = new StringBuilder(256);
        HeaderNames names = new HeaderNames(registry);
        b.append(names.device(h.interf(), h.index())).append(' ')
                .append(HeaderNames.type(h.type())).append(' ').append(names.subtype(h)).append(' ')
                .append(m.dir().label()).append(' ').append(m.connection().client()).append(' ')
                .append(m.connection().listen());
        for (Map.Entry<String, Object> e : FlatFields.flatten(m.decoded().body()).entrySet()) {
            b.append(' ').append(e.getKey()).append('=').append(CellText.of(e.getValue()));
        }
        return b.toString();
    }

    /**
     * Parses a stream pattern, first turning interface and message type names into their numbers
     * ({@code dev=laser} is {@code dev=6}, {@code type=DATA} is {@code type=1}).
     *
     * @throws IllegalArgumentException naming the token that is wrong
     */
    public static StreamPattern parsePattern(String text, CodecRegistry registry) {
        StringBuilder b = new StringBuilder();
        for (String token : text.trim().split("\\s+")) {
            String t = token;
            if (t.startsWith("dev=") && !isNumberOrStar(t.substring(4))) {
                int code = registry.interfaceCode(t.substring(4));
                if (code < 0) {
                    throw new IllegalArgumentException("stream pattern token '" + token + "': no interface named '"
                            + t.substring(4) + "'");
                }
                t = "dev=" + code;
            } else if (t.startsWith("type=") && !isNumberOrStar(t.substring(5))) {
                try {
                    t = "type=" + MessageType.valueOf(t.substring(5).toUpperCase(Locale.ROOT)).code();
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException("stream pattern token '" + token
                            + "': message types are DATA, CMD, REQ, RESP_ACK, SYNCH, RESP_NACK or 1..6");
                }
            }
            b.append(t).append(' ');
        }
        return StreamPattern.parse(b.toString());
    }

    private static boolean isNumberOrStar(String s) {
        return s.equals("*") || s.chars().allMatch(Character::isDigit) && !s.isEmpty();
    }
}
