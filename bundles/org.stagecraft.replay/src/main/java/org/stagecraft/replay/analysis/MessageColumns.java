package org.stagecraft.replay.analysis;

import java.util.Locale;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.wire.Direction;
import org.stagecraft.player.wire.MessageHeader;
import org.stagecraft.replay.log.HeaderNames;
import org.stagecraft.replay.log.LogMessage;

/**
 * The packet inspector's columns for one {@link LogMessage}, as text: time, connection, direction,
 * device, type, subtype, size and a one-line summary. Names are {@link HeaderNames}' (from the codec
 * registry, so a plug-in's interface shows by its name too), the same the exports write.
 */
public final class MessageColumns {
    private final HeaderNames names;
    private final MessageSummary summary;

    public MessageColumns(CodecRegistry registry) {
        this.names = new HeaderNames(registry);
        this.summary = new MessageSummary(registry);
    }

    public CodecRegistry registry() {
        return names.registry();
    }

    /** Seconds since {@code startNanos}, to the microsecond: "12.345678". */
    public static String time(long timeNanos, long startNanos) {
        return String.format(Locale.ROOT, "%.6f", (timeNanos - startNanos) / 1e9);
    }

    /** "#1" and the robot program's address. */
    public String connection(LogMessage m) {
        return m.connection() == null ? "" : "#" + m.connection().id() + " " + m.connection().client();
    }

    /** "c2s" (robot program to Player) or "s2c"; empty for connection-wide events. */
    public String direction(LogMessage m) {
        return direction(m.dir());
    }

    public static String direction(@Nullable Direction d) {
        return d == null ? "" : d.label();
    }

    /** "laser:0"; empty when the entry is not a Player message. */
    public String device(LogMessage m) {
        if (m.decoded() == null) {
            return "";
        }
        MessageHeader h = m.decoded().header();
        return device(h.interf(), h.index());
    }

    public String device(int interf, int index) {
        return names.device(interf, index);
    }

    /** The Player message type (DATA, CMD, REQ, RESP_ACK, SYNCH, RESP_NACK) or what else the entry is. */
    public String type(LogMessage m) {
        if (m.decoded() == null) {
            return m.kind().name();
        }
        return type(m.decoded().header().type());
    }

    public static String type(int code) {
        return HeaderNames.type(code);
    }

    /** Player's subtype name, e.g. "GET_GEOM", or the number when no layout names it. */
    public String subtype(LogMessage m) {
        if (m.decoded() == null) {
            return "";
        }
        return names.subtype(m.decoded().header());
    }

    /** Bytes on the wire. */
    public static String size(LogMessage m) {
        return Integer.toString(m.bytes().length);
    }

    public String summary(LogMessage m) {
        return summary.of(m);
    }

    /** All columns in table order (time relative to {@code startNanos}). */
    public String[] row(LogMessage m, long startNanos) {
        return new String[] { time(m.timeNanos(), startNanos), connection(m), direction(m), device(m), type(m),
                subtype(m), size(m), summary(m) };
    }

    /** Column titles matching {@link #row}. */
    public static final String[] TITLES = { "Time (s)", "Connection", "Dir", "Device", "Type", "Subtype", "Size",
            "Summary" };
}
