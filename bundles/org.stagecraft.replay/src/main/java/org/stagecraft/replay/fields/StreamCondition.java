package org.stagecraft.replay.fields;

import java.util.Locale;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.PlayerDecoder;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.player.wire.MessageType;
import org.stagecraft.replay.analysis.StreamSelector;
import org.stagecraft.spy.breakpoint.MessageCondition;
import org.stagecraft.spy.proxy.ConnectionInfo;
import org.stagecraft.spy.proxy.SpyStreams;
import org.stagecraft.streams.StreamPattern;

/**
 * A robot data breakpoint's text read: which messages from Player it looks at and the {@link Condition}
 * they must satisfy. Written as a device, an optional message type and a condition —
 * {@code laser:0 min(ranges) < 0.3}, {@code ranger:1 ranges[3] < 50 cm}, {@code position2d:0 stall == 1},
 * {@code bumper:0 any(bumpers)}, {@code position2d:0 DATA abs(vel.pa) > 30 deg/s} — or as any stream
 * selection and a condition split by a bar ({@code type=1 dev=6 index=* | min(ranges) < 0.3}).
 * A device without a message type means its DATA. Thread-safe.
 */
public final class StreamCondition implements MessageCondition {
    private final String text;
    private final StreamPattern streams;
    private final Condition condition;
    private final PlayerDecoder decoder;

    private StreamCondition(String text, StreamPattern streams, Condition condition, CodecRegistry registry) {
        this.text = text;
        this.streams = streams;
        this.condition = condition;
        this.decoder = new PlayerDecoder(registry);
    }

    /** @throws ConditionException saying what is wrong and where in {@code text} */
    public static StreamCondition parse(String text, CodecRegistry registry) {
        String t = text == null ? "" : text;
        int start = 0;
        while (start < t.length() && Character.isWhitespace(t.charAt(start))) {
            start++;
        }
        if (start == t.length()) {
            throw new ConditionException(t, 0, "empty: write a device and a condition, e.g. laser:0 min(ranges) < 0.3");
        }
        int bar = t.indexOf('|');
        String selector;
        int conditionAt;
        if (bar >= 0) {
            selector = t.substring(start, bar).strip();
            conditionAt = bar + 1;
        } else {
            int end = wordEnd(t, start);
            selector = t.substring(start, end);
            int next = skipSpace(t, end);
            int nextEnd = wordEnd(t, next);
            if (next < t.length() && isMessageType(t.substring(next, nextEnd))) {
                selector = selector + " " + t.substring(next, nextEnd);
                next = nextEnd;
            }
            conditionAt = next;
        }
        StreamPattern streams;
        try {
            streams = StreamSelector.parse(selector, registry);
        } catch (IllegalArgumentException e) {
            throw new ConditionException(t, start, e.getMessage());
        }
        if (conditionAt >= t.length() || t.substring(conditionAt).isBlank()) {
            throw new ConditionException(t, t.length(), "'" + selector + "' needs a condition after it, e.g. "
                    + selector + " min(ranges) < 0.3");
        }
        Condition c;
        try {
            c = Condition.parse(t.substring(conditionAt));
        } catch (ConditionException e) {
            throw new ConditionException(t, conditionAt + e.position(), e.reason());
        }
        return new StreamCondition(t.strip(), streams, c, registry);
    }

    private static int wordEnd(String t, int i) {
        while (i < t.length() && !Character.isWhitespace(t.charAt(i))) {
            i++;
        }
        return i;
    }

    private static int skipSpace(String t, int i) {
        while (i < t.length() && Character.isWhitespace(t.charAt(i))) {
            i++;
        }
        return i;
    }

    private static boolean isMessageType(String word) {
        for (MessageType m : MessageType.values()) {
            if (m.name().equalsIgnoreCase(word)) {
                return true;
            }
        }
        return word.equals("*");
    }

    public StreamPattern streams() {
        return streams;
    }

    public Condition condition() {
        return condition;
    }

    @Override
    public String text() {
        return text;
    }

    @Override
    public boolean watches(ConnectionInfo connection, MessageHeader header) {
        return streams.matches(SpyStreams.messageKey(connection, Direction.SERVER_TO_CLIENT, header));
    }

    /** Whether a message with this header is of the streams, wherever it was seen (a log's own key). */
    public boolean watches(org.stagecraft.streams.StreamKey key) {
        return streams.matches(key);
    }

    @Override
    public @Nullable Satisfied test(MessageHeader header, byte[] payload) {
        DecodedMessage m = decoder.decode(header, payload);
        if (m.hasProblem()) {
            return null; // a message that does not decode has no fields to test
        }
        Condition.Verdict v = condition.test(m.body());
        if (!v.holds()) {
            return null;
        }
        String name = decoder.registry().interfaceName(header.interf());
        String dev = (name == null ? "interface " + header.interf() : name.toLowerCase(Locale.ROOT)) + ":" + header.index();
        return new Satisfied(dev + " " + v.explanation(), v.decidingFields());
    }

    @Override
    public String toString() {
        return text;
    }
}
