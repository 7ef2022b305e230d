package org.stagecraft.replay.analysis;

import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;
import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;
import org.stagecraft.player.codec.CodecRegistry;
import org.stagecraft.player.codec.DecodedMessage;
import org.stagecraft.player.codec.FieldVisitor;
import org.stagecraft.player.codec.RawBody;
import org.stagecraft.replay.log.LogMessage;

/**
 * One line saying what a log entry holds, for the packet inspector: scalar fields as
 * {@code name=value} (structs flattened with dots), lists as {@code name[count] min..max}, and for
 * events, banners and problems what happened. Cut at {@link #MAX_LENGTH} characters.
 */
public final class MessageSummary {
    public static final int MAX_LENGTH = 160;

    public MessageSummary(CodecRegistry registry) {
        // the registry is not needed for the fields (bodies name them) but keeps the door open for
        // interface-specific summaries without changing callers
    }

    public String of(LogMessage m) {
        return switch (m.kind()) {
            case OPENED -> "connection opened" + (m.connection() == null ? ""
                    : ": " + m.connection().client() + " to " + m.connection().listen() + " (relayed to "
                            + m.connection().upstream() + ")");
            case CLOSED -> "connection closed" + (m.text().isEmpty() ? "" : ": " + m.text());
            case BANNER -> "banner \"" + banner(m.bytes()) + "\"";
            case UNFRAMED -> m.bytes().length + " bytes that are not a Player message"
                    + (m.text().isEmpty() ? "" : ": " + m.text());
            case DIAGNOSTIC, HOLD -> m.text();
            case FRAME -> cut(frame(Objects.requireNonNull(m.decoded())));
        };
    }

    private static String frame(DecodedMessage d) {
        if (d == null) {
            return "";
        }
        StringBuilder out = new StringBuilder();
        if (d.hasProblem()) {
            out.append("decode problem");
            if (d.problem().payloadOffset() >= 0) {
                out.append(" at payload byte ").append(d.problem().payloadOffset());
            }
            out.append(": ").append(d.problem().reason());
            return out.toString();
        }
        if (d.body() instanceof RawBody) {
            return "no decoder: " + d.header().size() + " payload bytes";
        }
        Line line = new Line(out);
        d.body().describe(line);
        return out.length() == 0 ? "(no payload)" : out.toString();
    }

    private static String banner(byte[] b) {
        int n = 0;
        while (n < b.length && b[n] != 0) {
            n++;
        }
        return new String(b, 0, n, StandardCharsets.ISO_8859_1);
    }

    private static String cut(String s) {
        return s.length() <= MAX_LENGTH ? s : s.substring(0, MAX_LENGTH - 1) + "\u2026";
    }

    /** Short number text: integers as such, others with up to 4 decimals (trailing zeros dropped). */
    static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        if (Double.isNaN(v) || Double.isInfinite(v)) {
            return Double.toString(v);
        }
        double a = Math.abs(v);
        if (a >= 1e6 || a < 1e-3) {
            return String.format(Locale.ROOT, "%.3e", v);
        }
        String s = String.format(Locale.ROOT, "%.4f", v);
        int end = s.length();
        while (s.charAt(end - 1) == '0') {
            end--;
        }
        if (s.charAt(end - 1) == '.') {
            end--;
        }
        return s.substring(0, end);
    }

    /** Writes the fields; stops writing (but keeps walking) once the line is long enough. */
    private static final class Line implements FieldVisitor {
        private final StringBuilder out;
        private final Deque<String> names = new ArrayDeque<>();
        /** Inside a list: its name, element count and numeric range; nested lists count only at the top. */
        private @Nullable String listName;
        private int listDepth, listCount;
        private double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;

        Line(StringBuilder out) {
            this.out = out;
        }

        private void field(@Nullable String name, String value) {
            if (out.length() > MAX_LENGTH) {
                return;
            }
            if (out.length() > 0) {
                out.append(' ');
            }
            out.append(path(name)).append('=').append(value);
        }

        private String path(@Nullable String name) {
            StringBuilder p = new StringBuilder();
            for (var it = names.descendingIterator(); it.hasNext();) {
                p.append(it.next()).append('.');
            }
            return p.append(name).toString();
        }

        private void number(@Nullable String name, double v) {
            if (listDepth > 0) {
                if (listDepth == 1 && name == null) { // a list of numbers: its range says most
                    listCount++;
                    min = Math.min(min, v);
                    max = Math.max(max, v);
                }
            } else {
                field(name, MessageSummary.number(v));
            }
        }

        @Override
        public void integer(@Nullable String name, long value) {
            number(name, value);
        }

        @Override
        public void float32(@Nullable String name, float value) {
            number(name, value);
        }

        @Override
        public void float64(@Nullable String name, double value) {
            number(name, value);
        }

        @Override
        public void text(@Nullable String name, String value) {
            if (listDepth > 0) {
                countElement(name);
            } else {
                field(name, "\"" + value + "\"");
            }
        }

        @Override
        public void opaque(@Nullable String name, byte[] value) {
            if (listDepth > 0) {
                countElement(name);
            } else {
                field(name, "<" + value.length + " bytes>");
            }
        }

        private void countElement(@Nullable String name) {
            if (listDepth == 1 && name == null) {
                listCount++;
            }
        }

        @Override
        public void beginStruct(@Nullable String name) {
            if (listDepth > 0) {
                countElement(name);
            } else {
                names.push(name == null ? "?" : name);
            }
        }

        @Override
        public void endStruct() {
            if (listDepth == 0) {
                names.pop();
            }
        }

        @Override
        public void beginList(@Nullable String name) {
            if (listDepth++ == 0) {
                listName = path(name == null ? "?" : name);
                listCount = 0;
                min = Double.POSITIVE_INFINITY;
                max = Double.NEGATIVE_INFINITY;
            } else {
                countElement(name);
            }
        }

        @Override
        public void endList() {
            if (--listDepth == 0 && out.length() <= MAX_LENGTH) {
                if (out.length() > 0) {
                    out.append(' ');
                }
                out.append(listName).append('[').append(listCount).append(']');
                if (min <= max) {
                    out.append(' ').append(MessageSummary.number(min)).append("..").append(MessageSummary.number(max));
                }
            }
        }
    }
}
