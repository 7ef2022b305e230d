package org.stagecraft.replay.analysis;

import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.replay.fields.FieldPath;
import org.stagecraft.streams.StreamPattern;

/**
 * Reads a plot series as a user types it: a device and a field path joined by a dot
 * ({@code "position2d.pos.px"}), a device and a path apart ({@code "ranger:1 min(ranges)"}), or any stream
 * selection and a path split by a bar ({@code "type=1 dev=4 index=* | pos.px"}). Devices and patterns are
 * read by {@link StreamSelector}, paths by {@link FieldPath}.
 */
public final class SeriesText {
    private SeriesText() {
    }

    /** The stream part and the field path part, trimmed. */
    public static String[] split(String text) {
        String t = text == null ? "" : text.strip();
        int bar = t.indexOf('|');
        if (bar >= 0) {
            return parts(t.substring(0, bar), t.substring(bar + 1), text);
        }
        int paren = t.indexOf('(');
        int space = paren >= 0 ? lastSpaceBefore(t, paren) : t.lastIndexOf(' ');
        if (space >= 0) {
            return parts(t.substring(0, space), t.substring(space + 1), text);
        }
        int dot = t.indexOf('.');
        if (dot > 0) {
            return parts(t.substring(0, dot), t.substring(dot + 1), text);
        }
        throw new IllegalArgumentException("'" + t + "' names no field: write e.g. position2d.pos.px, "
                + "ranger:1 min(ranges) or type=1 dev=4 | pos.px");
    }

    /** The space before the word holding {@code at}: an aggregate such as {@code mean( ranges )} may contain spaces. */
    private static int lastSpaceBefore(String t, int at) {
        int i = at - 1;
        while (i >= 0 && t.charAt(i) == ' ') {
            i--; // "mean (ranges)"
        }
        while (i >= 0 && t.charAt(i) != ' ') {
            i--;
        }
        return i;
    }

    private static String[] parts(String stream, String path, String text) {
        if (stream.isBlank() || path.isBlank()) {
            throw new IllegalArgumentException("'" + text.strip() + "' needs both a stream and a field path");
        }
        return new String[] { stream.strip(), path.strip() };
    }

    /** @throws IllegalArgumentException saying which part was not understood */
    public static SeriesSpec spec(String text, CodecRegistry registry) {
        String[] p = split(text);
        StreamPattern streams = StreamSelector.parse(p[0], registry);
        FieldPath path = FieldPath.parse(p[1]);
        return new SeriesSpec(text.strip(), streams, path::evaluate);
    }
}
