package org.stagecraft.streams;

import java.util.Objects;

import org.eclipse.jdt.annotation.Nullable;

/**
 * An immutable filter over {@link StreamKey}s; every field may be a wildcard. Addresses are matched
 * with globs in which {@code '*'} stands for any run of characters (e.g. {@code "*:6665"}); numeric
 * fields match one value or any.
 *
 * <p>
 * Text form ({@link #toString()} and {@link #parse(String)} round-trip):
 * {@code src=* dst=*:6665 type=1 dev=6 index=* subtype=1}. In {@code parse}, fields may come in any
 * order and missing ones are wildcards; {@code parse("")} is {@link #any()}.
 */
public final class StreamPattern {
    /** Value of a wildcarded numeric field. */
    private static final int ANY = -1;
    private static final String STAR = "*";
    private static final StreamPattern ANY_PATTERN = new StreamPattern(STAR, STAR, ANY, ANY, ANY, ANY);

    private final String source;
    private final String destination;
    private final int messageType;
    private final int deviceType;
    private final int index;
    private final int subtype;

    private StreamPattern(String source, String destination, int messageType, int deviceType, int index, int subtype) {
        this.source = source;
        this.destination = destination;
        this.messageType = messageType;
        this.deviceType = deviceType;
        this.index = index;
        this.subtype = subtype;
    }

    /** The pattern that matches every stream. */
    public static StreamPattern any() {
        return ANY_PATTERN;
    }

    /** The pattern matching exactly one stream. */
    public static StreamPattern exactly(StreamKey k) {
        return new StreamPattern(escapeCheck(k.source()), escapeCheck(k.destination()), k.messageType(),
                k.deviceType(), k.index(), k.subtype());
    }

    /** Source address glob ({@code '*'} matches any run of characters). */
    public StreamPattern source(String glob) {
        return new StreamPattern(checkGlob("src", glob), destination, messageType, deviceType, index, subtype);
    }

    /** Destination address glob ({@code '*'} matches any run of characters). */
    public StreamPattern destination(String glob) {
        return new StreamPattern(source, checkGlob("dst", glob), messageType, deviceType, index, subtype);
    }

    /** Message type 0..255. */
    public StreamPattern messageType(int value) {
        StreamKey.checkRange("messageType", value, StreamTypes.MESSAGE_TYPE_MAX);
        return new StreamPattern(source, destination, value, deviceType, index, subtype);
    }

    /** Device type (interface code) 0..65535. */
    public StreamPattern deviceType(int value) {
        StreamKey.checkRange("deviceType", value, StreamTypes.DEVICE_TYPE_MAX);
        return new StreamPattern(source, destination, messageType, value, index, subtype);
    }

    /** Device index 0..65535. */
    public StreamPattern index(int value) {
        StreamKey.checkRange("index", value, StreamTypes.INDEX_MAX);
        return new StreamPattern(source, destination, messageType, deviceType, value, subtype);
    }

    /** Subtype 0..255. */
    public StreamPattern subtype(int value) {
        StreamKey.checkRange("subtype", value, StreamTypes.SUBTYPE_MAX);
        return new StreamPattern(source, destination, messageType, deviceType, index, value);
    }

    /** Same pattern with the message type wildcarded. */
    public StreamPattern anyMessageType() {
        return new StreamPattern(source, destination, ANY, deviceType, index, subtype);
    }

    /** Same pattern with the device type wildcarded. */
    public StreamPattern anyDeviceType() {
        return new StreamPattern(source, destination, messageType, ANY, index, subtype);
    }

    /** Same pattern with the index wildcarded. */
    public StreamPattern anyIndex() {
        return new StreamPattern(source, destination, messageType, deviceType, ANY, subtype);
    }

    /** Same pattern with the subtype wildcarded. */
    public StreamPattern anySubtype() {
        return new StreamPattern(source, destination, messageType, deviceType, index, ANY);
    }

    public boolean matches(StreamKey k) {
        return (messageType == ANY || messageType == k.messageType())
                && (deviceType == ANY || deviceType == k.deviceType())
                && (index == ANY || index == k.index())
                && (subtype == ANY || subtype == k.subtype())
                && glob(source, k.source())
                && glob(destination, k.destination());
    }

    /**
     * Parses the text form, e.g. {@code "src=* dst=*:6665 type=1 dev=6 index=* subtype=1"}: whitespace
     * separated {@code field=value} tokens, fields {@code src, dst, type, dev, index, subtype}, each at
     * most once, {@code *} as a wildcard.
     *
     * @throws IllegalArgumentException naming the offending token
     */
    public static StreamPattern parse(String text) {
        Objects.requireNonNull(text, "text");
        StreamPattern p = ANY_PATTERN;
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (String token : text.trim().split("\\s+")) {
            if (token.isEmpty()) {
                continue;
            }
            int eq = token.indexOf('=');
            if (eq <= 0 || eq == token.length() - 1) {
                throw new IllegalArgumentException("stream pattern token '" + token
                        + "' is not field=value (fields: src, dst, type, dev, index, subtype)");
            }
            String field = token.substring(0, eq);
            String value = token.substring(eq + 1);
            if (!seen.add(field)) {
                throw new IllegalArgumentException("stream pattern token '" + token + "' repeats field " + field);
            }
            try {
                p = switch (field) {
                    case "src" -> p.source(value);
                    case "dst" -> p.destination(value);
                    case "type" -> value.equals(STAR) ? p.anyMessageType() : p.messageType(number(value));
                    case "dev" -> value.equals(STAR) ? p.anyDeviceType() : p.deviceType(number(value));
                    case "index" -> value.equals(STAR) ? p.anyIndex() : p.index(number(value));
                    case "subtype" -> value.equals(STAR) ? p.anySubtype() : p.subtype(number(value));
                    default -> throw new IllegalArgumentException(
                            "unknown field (fields: src, dst, type, dev, index, subtype)");
                };
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("stream pattern token '" + token + "': " + e.getMessage(), e);
            }
        }
        return p;
    }

    private static int number(String value) {
        try {
            return Integer.parseInt(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + value + "' is neither a number nor *");
        }
    }

    @Override
    public String toString() {
        return "src=" + source + " dst=" + destination + " type=" + num(messageType) + " dev=" + num(deviceType)
                + " index=" + num(index) + " subtype=" + num(subtype);
    }

    private static String num(int v) {
        return v == ANY ? STAR : Integer.toString(v);
    }

    @Override
    public boolean equals(@Nullable Object o) {
        return o instanceof StreamPattern p && p.source.equals(source) && p.destination.equals(destination)
                && p.messageType == messageType && p.deviceType == deviceType && p.index == index
                && p.subtype == subtype;
    }

    @Override
    public int hashCode() {
        return Objects.hash(source, destination, messageType, deviceType, index, subtype);
    }

    private static String checkGlob(String what, String glob) {
        Objects.requireNonNull(glob, what);
        if (glob.isEmpty()) {
            throw new IllegalArgumentException(what + " glob is empty (use * for any)");
        }
        for (int i = 0; i < glob.length(); i++) {
            if (Character.isWhitespace(glob.charAt(i))) {
                throw new IllegalArgumentException(what + " glob '" + glob + "' contains whitespace");
            }
        }
        return glob;
    }

    private static String escapeCheck(String address) {
        if (address.indexOf('*') >= 0) {
            throw new IllegalArgumentException("address '" + address + "' contains '*'");
        }
        return address;
    }

    /** Glob match where '*' matches any (possibly empty) run of characters; iterative, linear-ish. */
    static boolean glob(String pattern, String text) {
        if (pattern.equals(STAR)) {
            return true;
        }
        int p = 0;
        int t = 0;
        int starP = -1;
        int starT = 0;
        while (t < text.length()) {
            if (p < pattern.length() && pattern.charAt(p) == '*') {
                starP = p++;
                starT = t;
            } else if (p < pattern.length() && pattern.charAt(p) == text.charAt(t)) {
                p++;
                t++;
            } else if (starP >= 0) {
                p = starP + 1;
                t = ++starT;
            } else {
                return false;
            }
        }
        while (p < pattern.length() && pattern.charAt(p) == '*') {
            p++;
        }
        return p == pattern.length();
    }
}
