package org.stagecraft.player.msg;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import org.eclipse.jdt.annotation.Nullable;

/** Immutable bytes: Player strings (char arrays whose count includes the NUL) and byte arrays. */
public final class ByteArray {
    public static final ByteArray EMPTY = new ByteArray(new byte[0]);

    private final byte[] values;

    private ByteArray(byte[] values) {
        this.values = values;
    }

    public static ByteArray of(byte... values) {
        return new ByteArray(values.clone());
    }

    /** A Player string as it goes on the wire: the text followed by one NUL. */
    public static ByteArray ofText(String text) {
        byte[] t = text.getBytes(StandardCharsets.ISO_8859_1);
        return new ByteArray(Arrays.copyOf(t, t.length + 1));
    }

    static ByteArray adopt(byte[] values) {
        return new ByteArray(values);
    }

    public int size() {
        return values.length;
    }

    public byte get(int i) {
        return values[i];
    }

    /** Unsigned value of byte i. */
    public int unsigned(int i) {
        return values[i] & 0xFF;
    }

    public byte[] toArray() {
        return values.clone();
    }

    byte[] raw() {
        return values;
    }

    /** The bytes up to the first NUL, as text (Player strings are C strings). */
    public String text() {
        int end = 0;
        while (end < values.length && values[end] != 0) {
            end++;
        }
        return new String(values, 0, end, StandardCharsets.ISO_8859_1);
    }

    @Override
    public boolean equals(@Nullable Object o) {
        return o instanceof ByteArray b && Arrays.equals(values, b.values);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(values);
    }

    @Override
    public String toString() {
        return text();
    }
}
