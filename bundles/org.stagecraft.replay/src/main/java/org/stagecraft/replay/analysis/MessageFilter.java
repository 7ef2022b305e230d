package org.stagecraft.replay.analysis;

import java.util.Locale;
import java.util.Optional;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.replay.log.LogMessage;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamKey;
import org.stagecraft.streams.StreamMessage;
import org.stagecraft.streams.StreamPattern;

/**
 * Which log entries the packet inspector shows: a stream pattern (the bus's wildcard syntax, e.g.
 * {@code "type=1 dev=6"}, or a device such as {@code "laser:0"}, see {@link StreamSelector}) and free text looked for, ignoring case, in the device, type, subtype,
 * connection and summary columns. Either may be empty (then it lets everything through). Entries
 * without a stream key (connection events, banners) pass only an empty pattern.
 */
public final class MessageFilter {
    private final @Nullable StreamPattern pattern;
    private final String patternText;
    private final String text;
    private final MessageColumns columns;

    private MessageFilter(@Nullable StreamPattern pattern, String patternText, String text, MessageColumns columns) {
        this.pattern = pattern;
        this.patternText = patternText;
        this.text = text;
        this.columns = columns;
    }

    /** Everything. */
    public static MessageFilter all(MessageColumns columns) {
        return new MessageFilter(null, "", "", columns);
    }

    /**
     * @param patternText a stream pattern or device ({@link StreamSelector}), or blank for every stream
     * @param freeText    text to look for, or blank
     * @throws IllegalArgumentException when the pattern does not parse (its message says why)
     */
    public static MessageFilter of(String patternText, String freeText, MessageColumns columns) {
        String p = patternText == null ? "" : patternText.strip();
        String t = freeText == null ? "" : freeText.strip().toLowerCase(Locale.ROOT);
        return new MessageFilter(p.isEmpty() ? null : StreamSelector.parse(p, columns.registry()), p, t, columns);
    }

    public boolean isEmpty() {
        return pattern == null && text.isEmpty();
    }

    public String patternText() {
        return patternText;
    }

    public String text() {
        return text;
    }

    public boolean matches(LogMessage m) {
        if (pattern != null) {
            Optional<StreamKey> key = key(m);
            if (key.isEmpty() || !pattern.matches(key.get())) {
                return false;
            }
        }
        if (!text.isEmpty()) {
            return contains(columns.device(m)) || contains(columns.type(m)) || contains(columns.subtype(m))
                    || contains(columns.connection(m)) || contains(columns.summary(m));
        }
        return true;
    }

    /**
     * The key the entry is published under on replay, if it is published; for a hold's row that carried a
     * message (an injected command, a held-back one, a breakpoint's hit), that message's stream, so a
     * filter on a device shows what the hold did to it.
     */
    public static Optional<StreamKey> key(LogMessage m) {
        if (m.kind() == LogMessage.Kind.HOLD) {
            Direction dir = m.dir();
            DecodedMessage d = m.decoded();
            return d == null || dir == null ? Optional.empty() : Optional.of(SpyStreams.messageKey(m.connection(), dir, d.header()));
        }
        return m.toStreamMessage().map(StreamMessage::key);
    }

    private boolean contains(String s) {
        return s.toLowerCase(Locale.ROOT).contains(text);
    }

    @Override
    public String toString() {
        return isEmpty() ? "everything" : "pattern '" + patternText + "', text '" + text + "'";
    }
}
